#pragma once
// An exact shadow oracle for scenes with mesh models (issue #14: faces that may be
// non-convex, have holes, or belong to open surfaces), written independently of the
// shadow engine. A point X of a face is in shadow for a light when the light is not
// strictly on the outer side of X's face plane, or when the open segment from X to the
// light (the open ray toward the sun, along -directional) crosses an occluder:
//
// - a face of a mesh model: the segment crosses the face's plane at a single point
//   strictly inside the face (inside its outer ring, outside every hole). For a closed
//   solid this is "the segment meets its interior" up to measure zero: a segment through
//   the interior must enter or leave it across the boundary, the union of the faces, and
//   does so through a face's relative interior unless it passes an edge or a corner
//   (then the verdict below is `degenerate`, or another face blocks it);
// - a convex object: test::segment_blocked (oracle.h).
//
// The crossing parameter is the exact rational t = f(X) / (f(X) - f(Q)) toward a point Q
// (f the face's plane function; t in (0, 1) exactly when f(X) and f(Q) have strictly
// opposite signs) and t = -f(X) / (n . D) along the sun's ray D (t > 0 exactly when f(X)
// and n . D have strictly opposite signs): a segment in the plane, or one touching it
// only at X or at the light, crosses nothing. The crossing point is then located in the
// face with planar_region.h. A crossing exactly on a ring (a face's edge or corner) is
// measure zero: unless another face blocks the segment, the point's verdict is
// `degenerate` and the caller counts it apart.
//
// Only candidate faces are tested exactly: those whose bounding box, widened by a
// micrometre, the segment meets in doubles (a slab test). The widening exceeds every
// rounding of the doubles by orders of magnitude, so no face the exact segment crosses
// is left out; the verdict itself is exact.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "oracle.h"
#include "penumbra/base/random.h"
#include "penumbra/scene/model_import.h"
#include "penumbra/scene/scene.h"
#include "planar_region.h"

namespace penumbra::test {

enum class Verdict { shadow, lit, degenerate };

// returns true when the light is strictly on the positive (outer) side of plane.
inline bool strictly_outside(const Plane3& plane, const Light& light) {
  if (const auto* point = std::get_if<PointLight>(&light.source))
    return plane.oriented_side(to_exact(point->position)) == CGAL::ON_POSITIVE_SIDE;
  const Vec3d& d = std::get<DirectionalLight>(light.source).direction;
  return CGAL::is_negative(plane.orthogonal_vector() * to_exact_vector(d));
}

// The open segment from X to a point light, or the open ray from X toward the sun:
// X + t D for t in (0, 1), or t > 0.
struct Sight {
  Point3 from;
  Vector3 direction;
  bool bounded = true;
  Point3 to;                                      // the light, when bounded
  std::array<double, 3> from_d{}, direction_d{};  // for the box prefilter only

  Sight(const Point3& x, const Light& light) : from(x) {
    if (const auto* point = std::get_if<PointLight>(&light.source)) {
      to = to_exact(point->position);
      direction = to - x;
    } else {
      direction = -to_exact_vector(std::get<DirectionalLight>(light.source).direction);
      bounded = false;
    }
    const Vec3d a = to_double(from), b = to_double(direction);
    for (int k = 0; k < 3; ++k) {
      from_d[k] = a[k];
      direction_d[k] = b[k];
    }
  }
};

// A face of a mesh model as an occluder: its plane, its region and a widened box.
struct OccluderFace {
  Plane3 plane;
  PlanarRegion region;
  std::array<double, 6> box;  // min x, y, z, max x, y, z, widened

  explicit OccluderFace(const PlanarFace& face)
      : plane(face.plane), region(face.plane.orthogonal_vector(), face.outer, face.holes) {
    const double inf = std::numeric_limits<double>::infinity();
    box = {inf, inf, inf, -inf, -inf, -inf};
    for (const Point3& p : face.outer) {  // the holes lie inside the outer ring
      const Vec3d q = to_double(p);
      for (int k = 0; k < 3; ++k) {
        box[k] = std::min(box[k], q[k]);
        box[k + 3] = std::max(box[k + 3], q[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      box[k] -= 1e-6 + 1e-9 * std::abs(box[k]);
      box[k + 3] += 1e-6 + 1e-9 * std::abs(box[k + 3]);
    }
  }

  // returns true when the segment may meet the box (a slab test in doubles).
  bool may_meet(const Sight& sight) const {
    double low = 0, high = sight.bounded ? 1 : std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double o = sight.from_d[k], d = sight.direction_d[k];
      if (d == 0) {
        if (o < box[k] || o > box[k + 3]) return false;
        continue;
      }
      double a = (box[k] - o) / d, b = (box[k + 3] - o) / d;
      if (a > b) std::swap(a, b);
      low = std::max(low, a);
      high = std::min(high, b);
      if (low > high) return false;
    }
    return true;
  }

  // returns where the open segment crosses the face: inside (it blocks), on a ring, or
  // outside (no single crossing of the plane in the open segment, or one off the face).
  Place crossing(const Sight& sight) const {
    if (!may_meet(sight)) return Place::outside;
    const CGAL::Oriented_side at_x = plane.oriented_side(sight.from);
    if (at_x == CGAL::ON_ORIENTED_BOUNDARY) return Place::outside;  // t = 0, or in the plane
    const Exact fx = plane.a() * sight.from.x() + plane.b() * sight.from.y() +
                     plane.c() * sight.from.z() + plane.d();
    Exact t;
    if (sight.bounded) {
      const CGAL::Oriented_side at_q = plane.oriented_side(sight.to);
      if (at_q == at_x || at_q == CGAL::ON_ORIENTED_BOUNDARY) return Place::outside;
      const Exact fq = plane.a() * sight.to.x() + plane.b() * sight.to.y() +
                       plane.c() * sight.to.z() + plane.d();
      t = fx / (fx - fq);
    } else {
      const Exact rate = plane.orthogonal_vector() * sight.direction;
      if (CGAL::sign(rate) != -CGAL::sign(fx)) return Place::outside;  // parallel or away
      t = -fx / rate;
    }
    return region.locate(sight.from + t * sight.direction);
  }
};

// The occluders of a scene: its convex objects and every face of its mesh models.
class MeshOracle {
 public:
  // convex: the scene's objects that are not parts of mesh models.
  MeshOracle(std::vector<const ConvexPolyhedron*> convex,
             const std::vector<const ImportedModel*>& models)
      : convex_(std::move(convex)) {
    for (const ImportedModel* model : models)
      for (const ModelPart& part : model->parts)
        for (const PlanarFace& face : part.faces) faces_.emplace_back(face);
  }

  std::size_t mesh_faces() const { return faces_.size(); }

  // returns the verdict at x, a point of a face with the given (outward) plane.
  Verdict verdict(const Plane3& plane, const Point3& x, const Light& light) const {
    if (!strictly_outside(plane, light)) return Verdict::shadow;
    for (const ConvexPolyhedron* solid : convex_)
      if (segment_blocked(x, light, *solid)) return Verdict::shadow;
    const Sight sight(x, light);
    bool touched = false;
    for (const OccluderFace& face : faces_) {
      const Place place = face.crossing(sight);
      if (place == Place::inside) return Verdict::shadow;
      touched = touched || place == Place::boundary;
    }
    return touched ? Verdict::degenerate : Verdict::lit;
  }

 private:
  std::vector<const ConvexPolyhedron*> convex_;
  std::vector<OccluderFace> faces_;
};

// returns up to count random rational points strictly inside region, a polygon with holes
// in plane. Coordinates are drawn uniformly in the bounding rectangle of the outer ring
// projected along the normal's largest component (i, j: the two other axes), the third
// solved exactly from the plane's equation, and the point kept when it is strictly inside
// (rejection, which holds for non-convex rings and holes alike). Sliver faces may give
// fewer points: at most 64 count draws are made.
inline std::vector<Point3> sample_region(const Plane3& plane, const PlanarRegion& region, int count,
                                         SplitMix64& random) {
  const std::array<Exact, 3> n = {plane.a(), plane.b(), plane.c()};
  int k = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (CGAL::abs(n[axis]) > CGAL::abs(n[k])) k = axis;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const auto coordinate = [](const Point3& p, int axis) { return p.cartesian(axis); };
  Exact lo_i = coordinate(region.outer()[0], i), hi_i = lo_i;
  Exact lo_j = coordinate(region.outer()[0], j), hi_j = lo_j;
  for (const Point3& p : region.outer()) {
    lo_i = std::min<Exact>(lo_i, coordinate(p, i));
    hi_i = std::max<Exact>(hi_i, coordinate(p, i));
    lo_j = std::min<Exact>(lo_j, coordinate(p, j));
    hi_j = std::max<Exact>(hi_j, coordinate(p, j));
  }
  const Exact steps = Exact(1 << 24);
  const auto fraction = [&] { return Exact(static_cast<int>(random.next() >> 40)) / steps; };
  std::vector<Point3> points;
  for (int draw = 0; draw < 64 * count && static_cast<int>(points.size()) < count; ++draw) {
    std::array<Exact, 3> c;
    c[i] = lo_i + (hi_i - lo_i) * fraction();
    c[j] = lo_j + (hi_j - lo_j) * fraction();
    c[k] = -(plane.d() + n[i] * c[i] + n[j] * c[j]) / n[k];
    const Point3 p(c[0], c[1], c[2]);
    if (region.locate(p) == Place::inside) points.push_back(p);
  }
  return points;
}

}  // namespace penumbra::test
