#pragma once
// Small builders and exact classifiers shared by the linear-source tests.

#include <CGAL/Polygon_2.h>

#include <algorithm>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/region.h"

namespace penumbra::test {

// returns the axis-aligned box [x0, x1] x [y0, y1] x [z0, z1].
inline ConvexPolyhedron box(double x0, double y0, double z0, double x1, double y1, double z1) {
  std::vector<Point3> corners;
  for (int k = 0; k < 8; ++k)
    corners.emplace_back((k & 1) ? x1 : x0, (k & 2) ? y1 : y0, (k & 4) ? z1 : z0);
  return ConvexPolyhedron::hull(corners);
}

// returns the face of solid that lies in plane (precondition: there is one).
inline const Face& face_with_plane(const ConvexPolyhedron& solid, const Plane3& plane) {
  return *std::find_if(solid.faces().begin(), solid.faces().end(),
                       [&](const Face& f) { return f.plane == plane; });
}

// returns the exact side of p relative to a region (polygons with holes).
inline CGAL::Bounded_side side_of(const Region2& region, const Point2& p) {
  using Polygon = CGAL::Polygon_2<Kernel>;
  for (const Polygon2& polygon : region.polygons) {
    const auto outer = Polygon(polygon.outer.begin(), polygon.outer.end()).bounded_side(p);
    if (outer == CGAL::ON_UNBOUNDED_SIDE) continue;
    if (outer == CGAL::ON_BOUNDARY) return CGAL::ON_BOUNDARY;
    for (const Ring2& hole : polygon.holes) {
      const auto in_hole = Polygon(hole.begin(), hole.end()).bounded_side(p);
      if (in_hole != CGAL::ON_UNBOUNDED_SIDE)
        return in_hole == CGAL::ON_BOUNDARY ? CGAL::ON_BOUNDARY : CGAL::ON_UNBOUNDED_SIDE;
    }
    return CGAL::ON_BOUNDED_SIDE;
  }
  return CGAL::ON_UNBOUNDED_SIDE;
}

}  // namespace penumbra::test
