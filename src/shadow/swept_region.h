#pragma once
// The closed region W = conv(face, source) swept by the segments from a face to a tube (or
// to a point light: both ends the same), with the planes that certainly support it, for a
// separating-plane test against occluders in interval arithmetic (private to
// shadow_map.cpp). It lists the objects that may shadow a face the shadow maps do not
// compute (beyond a light's sphere of lighting): a superset, so values computed with it stay
// exact (docs/render.md).

#include <utility>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

class SweptRegion {
 public:
  SweptRegion(const Face& face, const Point3& q1, const Point3& q2);

  // returns true when a plane certainly separates the occluder's interior from W: the
  // occluder strictly on the positive side of a supporting plane of W, or W strictly on the
  // outer side of one of the occluder's faces. Then no segment from the face to the source
  // meets the occluder: it casts no shadow on the face.
  bool separated_from(const ConvexPolyhedron& solid) const;

 private:
  // keeps the plane through origin with normal, oriented so that W is on its closed
  // negative side, when every point of W is certainly on one closed side of it.
  void add(const IntervalPoint& origin, const IntervalPoint& normal);

  std::vector<IntervalPoint> points_;
  std::vector<std::pair<IntervalPoint, IntervalPoint>> planes_;  // (origin, normal)
};

}  // namespace penumbra::detail
