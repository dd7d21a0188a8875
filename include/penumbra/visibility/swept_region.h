#pragma once
// The closed region W swept by the segments from a face to a source (Nishita 1985 section
// 3.2, last paragraph: only an occluder meeting W can shadow the face): conv(face, source)
// for a point light, a tube or an area source, the prism face + t s (t >= 0, s toward the sun) for
// the sun; with the planes that certainly support it, for separating-plane tests in interval
// arithmetic. The broad phase drops an occluder (or a box of them) that a plane certainly
// separates from W: a superset of the occluders that shadow the face is kept, so every
// result computed from it stays exact.

#include <optional>
#include <utility>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/interval.h"
#include "penumbra/visibility/light_position.h"

namespace penumbra {

class SweptRegion {
 public:
  // the region from face to the tube q1 q2 (to a point light: q1 = q2).
  SweptRegion(const Face& face, const Point3& q1, const Point3& q2);
  // the region from face to a convex source: a point, a segment's two ends, or a convex
  // polygon's vertices in cycle order with no three on a line (an area source).
  SweptRegion(const Face& face, const std::vector<Point3>& source);
  // the region from a convex receiver (a face's vertices in cycle order, or one point) to a
  // convex source as above: conv(receiver, source).
  SweptRegion(const std::vector<Point3>& receiver, const std::vector<Point3>& source);
  // the region from face to a point light, or toward the sun.
  SweptRegion(const Face& face, const LightPosition& light);

  // returns true when a plane certainly separates the occluder's interior from W: the
  // occluder strictly on the positive side of a supporting plane of W, or W strictly on the
  // outer side of one of the occluder's faces. Then no segment from the face to the source
  // meets the occluder: it casts no shadow on the face.
  bool separated_from(const ConvexPolyhedron& solid) const;

  // returns true when a supporting plane of W certainly has the whole box strictly on its
  // positive side (nothing in the box can shadow the face).
  bool separated_from(const CGAL::Bbox_3& box) const;

 private:
  // keeps the plane through origin with normal, oriented so that W is on its closed
  // negative side, when every point of W is certainly on one closed side of it; the points
  // on_plane (indices into points_) lie on it exactly by construction and are not asked. For
  // the sun's prism the normal must be orthogonal to the direction (exactly).
  void add(const IntervalPoint& origin, const IntervalPoint& normal,
           const std::vector<std::size_t>& on_plane);

  std::vector<IntervalPoint> points_;        // the face's vertices, and the source's ends
  std::optional<IntervalPoint> toward_sun_;  // the prism's direction s, for the sun
  std::vector<std::pair<IntervalPoint, IntervalPoint>> planes_;  // (origin, normal)
};

}  // namespace penumbra
