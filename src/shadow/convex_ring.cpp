#include "convex_ring.h"

#include <algorithm>

#include "rational_enclosure.h"

namespace penumbra::detail {

Probe::Probe(const RationalPoint2& p) : point(p), at{enclosure(p.x()), enclosure(p.y())} {}

ConvexRing::ConvexRing(std::vector<RationalPoint2> points) : points_(std::move(points)) {
  for (const RationalPoint2& p : points_) {
    const std::array<Interval, 2> a{enclosure(p.x()), enclosure(p.y())};
    for (int k = 0; k < 2; ++k) {
      low_[k] = approx_.empty() ? a[k].inf() : std::min(low_[k], a[k].inf());
      high_[k] = approx_.empty() ? a[k].sup() : std::max(high_[k], a[k].sup());
    }
    approx_.push_back(a);
  }
}

bool ConvexRing::outside_box(const std::array<Interval, 2>& at) const {
  for (int k = 0; k < 2; ++k)
    if (at[k].sup() < low_[k] || at[k].inf() > high_[k]) return true;
  return false;
}

Interval ConvexRing::turn(std::size_t k, const std::array<Interval, 2>& at) const {
  const auto& a = approx_[k];
  const auto& b = approx_[(k + 1) % approx_.size()];
  return (b[0] - a[0]) * (at[1] - a[1]) - (b[1] - a[1]) * (at[0] - a[0]);
}

bool ConvexRing::contains(const Probe& p) const {
  if (empty() || outside_box(p.at)) return false;
  const std::size_t n = points_.size();
  CGAL::Protect_FPU_rounding<true> upward;
  for (std::size_t k = 0; k < n; ++k) {
    const Interval t = turn(k, p.at);
    if (t.sup() < 0) return false;
    if (t.inf() >= 0) continue;
    if (CGAL::orientation(points_[k], points_[(k + 1) % n], p.point) == CGAL::RIGHT_TURN)
      return false;
  }
  return true;
}

bool ConvexRing::strictly_contains(const Probe& p) const {
  if (empty() || outside_box(p.at)) return false;
  const std::size_t n = points_.size();
  CGAL::Protect_FPU_rounding<true> upward;
  for (std::size_t k = 0; k < n; ++k) {
    const Interval t = turn(k, p.at);
    if (t.sup() <= 0) return false;
    if (t.inf() > 0) continue;
    if (CGAL::orientation(points_[k], points_[(k + 1) % n], p.point) != CGAL::LEFT_TURN)
      return false;
  }
  return true;
}

std::optional<bool> ConvexRing::maybe_contains(const std::array<Interval, 2>& at) const {
  if (empty() || outside_box(at)) return false;
  bool certain = true;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const Interval t = turn(k, at);
    if (t.sup() < 0) return false;
    if (t.inf() < 0) certain = false;
  }
  if (!certain) return std::nullopt;
  return true;
}

FaceRegion::FaceRegion(std::vector<ConvexRing> pieces,
                       std::vector<std::vector<RationalPoint2>> boundary)
    : pieces_(std::move(pieces)), boundary_(std::move(boundary)) {
  for (const auto& ring : boundary_) points_.insert(points_.end(), ring.begin(), ring.end());
}

bool FaceRegion::contains(const Probe& p) const {
  return std::any_of(pieces_.begin(), pieces_.end(),
                     [&](const ConvexRing& piece) { return piece.contains(p); });
}

std::optional<bool> FaceRegion::maybe_contains(const std::array<Interval, 2>& at) const {
  bool certain = true;
  for (const ConvexRing& piece : pieces_) {
    const std::optional<bool> in = piece.maybe_contains(at);
    if (!in) certain = false;
    if (in == true) return true;
  }
  if (!certain) return std::nullopt;
  return false;
}

std::array<Interval, 2> interval_point(const Pencil& pencil, const Interval& s, const Interval& r) {
  const auto& [a0, a1, b0, b1] = pencil.enclosures();
  return {a0[0] + s * a1[0] + r * (b0[0] + s * b1[0]), a0[1] + s * a1[1] + r * (b0[1] + s * b1[1])};
}

FilteredAffine::FilteredAffine(const Affine2& exact)
    : exact_(exact), d_(enclosure(exact.d)), e_(enclosure(exact.e)), f_(enclosure(exact.f)) {}

FilteredAffine::FilteredAffine(const std::array<Interval, 3>& enclosures,
                               std::function<Affine2()> make)
    : make_(std::move(make)), d_(enclosures[0]), e_(enclosures[1]), f_(enclosures[2]) {}

std::optional<CGAL::Sign> FilteredAffine::maybe_sign(const std::array<Interval, 2>& at) const {
  const Interval value = d_ * at[0] + e_ * at[1] + f_;
  if (value.inf() > 0) return CGAL::POSITIVE;
  if (value.sup() < 0) return CGAL::NEGATIVE;
  if (value.inf() == 0 && value.sup() == 0) return CGAL::ZERO;
  return std::nullopt;
}

CGAL::Sign FilteredAffine::sign(const Probe& p) const {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    if (const auto certain = maybe_sign(p.at)) return *certain;
  }
  return CGAL::sign(exact()(p.point));
}

}  // namespace penumbra::detail
