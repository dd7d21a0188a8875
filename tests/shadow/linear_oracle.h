#pragma once
// Exact oracles for a linear source, written independently of the shadow engine
// (issue #4, item 8a): a point X is in the penumbra-or-umbra of a convex solid V
// when the closed triangle (X, Q1, Q2) meets V's interior, and in its umbra when
// the segments (X, Q1) and (X, Q2) both do. "Meets the interior" is decided by
// clipping the simplex to the closed solid (Sutherland-Hodgman in 3D, exact) and
// testing the clipped set's vertex centroid, which lies in its relative interior:
// if any point of the clipped set is interior to V, so is every relative-interior
// point, since V is convex.

#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra::test {

inline Exact plane_value(const Plane3& plane, const Point3& p) {
  return plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d();
}

// returns true when the convex hull of simplex (2 or 3 points) meets solid's interior.
inline bool simplex_meets_interior(std::vector<Point3> polygon, const ConvexPolyhedron& solid) {
  for (const Face& face : solid.faces()) {
    std::vector<Point3> kept;
    const std::size_t n = polygon.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Point3& a = polygon[k];
      const Point3& b = polygon[(k + 1) % n];
      const Exact fa = plane_value(face.plane, a), fb = plane_value(face.plane, b);
      if (fa <= 0) kept.push_back(a);
      if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) kept.push_back(a + (fa / (fa - fb)) * (b - a));
    }
    polygon = std::move(kept);
    if (polygon.empty()) return false;
  }
  Vector3 sum = CGAL::NULL_VECTOR;
  for (const Point3& p : polygon) sum = sum + (p - CGAL::ORIGIN);
  const Point3 centre = CGAL::ORIGIN + sum / static_cast<int>(polygon.size());
  for (const Face& face : solid.faces())
    if (plane_value(face.plane, centre) >= 0) return false;
  return true;
}

inline bool triangle_blocked(const Point3& x, const Point3& q1, const Point3& q2,
                             const ConvexPolyhedron& solid) {
  return simplex_meets_interior({x, q1, q2}, solid);
}

inline bool segment_meets_interior(const Point3& x, const Point3& q,
                                   const ConvexPolyhedron& solid) {
  return simplex_meets_interior({x, q}, solid);
}

}  // namespace penumbra::test
