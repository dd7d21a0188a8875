#pragma once
// Exact point location in the sweep of exact_umbra.cpp with an interval filter in front
// ("exact numbers only where needed", docs/performance.md): a point carries the interval
// enclosure of its rational coordinates, a convex ring its bounding box and its vertices'
// enclosures, an affine function of the face its coefficients' enclosures. A sign the
// intervals certify is the exact sign; otherwise the rationals decide.

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "pencil.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

// A rational point of a face's frame with the enclosure of its coordinates.
struct Probe {
  explicit Probe(const RationalPoint2& point);
  const RationalPoint2& point;
  std::array<Interval, 2> at;
};

// A closed convex counter-clockwise ring of rational points (fewer than three: empty).
class ConvexRing {
 public:
  ConvexRing() = default;
  explicit ConvexRing(std::vector<RationalPoint2> points);

  const std::vector<RationalPoint2>& points() const { return points_; }
  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.size() < 3; }
  // true when the point lies in the closed ring.
  bool contains(const Probe& p) const;
  bool contains(const RationalPoint2& p) const { return contains(Probe(p)); }
  // the same for a point known by an enclosure only: nullopt when the intervals cannot
  // tell (needs upward rounding, CGAL::Protect_FPU_rounding<true>).
  std::optional<bool> maybe_contains(const std::array<Interval, 2>& at) const;
  // true when the point lies in the open ring (inside, off every edge).
  bool strictly_contains(const Probe& p) const;
  // the enclosures of the vertices' coordinates, in order.
  const std::vector<std::array<Interval, 2>>& enclosures() const { return approx_; }
  // a box that holds the ring (empty ring: the point 0, 0).
  std::array<Interval, 2> box() const {
    return {Interval(low_[0], high_[0]), Interval(low_[1], high_[1])};
  }

 private:
  bool outside_box(const std::array<Interval, 2>& at) const;
  // (b - a) x (p - a) for the edge a -> b from vertex k: negative when p lies to its right.
  Interval turn(std::size_t k, const std::array<Interval, 2>& at) const;

  std::vector<RationalPoint2> points_;
  std::vector<std::array<Interval, 2>> approx_;
  double low_[2] = {0, 0}, high_[2] = {0, 0};  // the box that encloses the vertices
};

// A face of the sweep: the union of closed convex pieces (one for a convex face; the convex
// pieces of a mesh face, which may be non-convex and have holes), with the rings of its
// boundary (outer and holes), whose edges and vertices the sweep cuts along.
class FaceRegion {
 public:
  FaceRegion() = default;
  FaceRegion(std::vector<ConvexRing> pieces, std::vector<std::vector<RationalPoint2>> boundary);
  explicit FaceRegion(const ConvexRing& convex) : FaceRegion({convex}, {convex.points()}) {}

  // every vertex of the boundary's rings.
  const std::vector<RationalPoint2>& points() const { return points_; }
  const std::vector<std::vector<RationalPoint2>>& boundary() const { return boundary_; }
  const std::vector<ConvexRing>& pieces() const { return pieces_; }
  bool contains(const Probe& p) const;
  bool contains(const RationalPoint2& p) const { return contains(Probe(p)); }
  // as ConvexRing::maybe_contains, for the union.
  std::optional<bool> maybe_contains(const std::array<Interval, 2>& at) const;

 private:
  std::vector<ConvexRing> pieces_;
  std::vector<std::vector<RationalPoint2>> boundary_;
  std::vector<RationalPoint2> points_;
};

// The enclosure of the pencil's point (s, r) for enclosures of s and r (upward rounding).
std::array<Interval, 2> interval_point(const Pencil& pencil, const Interval& s, const Interval& r);

// An affine function d x + e y + f of the frame with a filtered sign: its rational form
// given, or made by make when first asked for (enclosures must then hold its coefficients).
class FilteredAffine {
 public:
  explicit FilteredAffine(const Affine2& exact);
  FilteredAffine(const std::array<Interval, 3>& enclosures, std::function<Affine2()> make);
  const Affine2& exact() const {
    if (!exact_) exact_ = make_();
    return *exact_;
  }
  // the sign of the function at p.
  CGAL::Sign sign(const Probe& p) const;
  // the sign at a point known by an enclosure only, or nullopt when the intervals cannot
  // tell (needs upward rounding).
  std::optional<CGAL::Sign> maybe_sign(const std::array<Interval, 2>& at) const;
  // the enclosures of d, e and f.
  std::array<Interval, 3> enclosures() const { return {d_, e_, f_}; }

 private:
  mutable std::optional<Affine2> exact_;
  std::function<Affine2()> make_;
  Interval d_, e_, f_;
};

}  // namespace penumbra::detail
