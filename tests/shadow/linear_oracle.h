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

// returns the vertices of the convex hull of simplex (2 or 3 points) clipped to the closed
// solid (Sutherland-Hodgman, exact): empty when they do not meet.
inline std::vector<Point3> clip_to_solid(std::vector<Point3> polygon,
                                         const ConvexPolyhedron& solid) {
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
    if (polygon.empty()) break;
  }
  return polygon;
}

// returns true when a clipped set (clip_to_solid's, not empty) has a point in the solid's
// interior: then so does its vertex centroid, a point of its relative interior.
inline bool clipped_meets_interior(const std::vector<Point3>& clipped,
                                   const ConvexPolyhedron& solid) {
  Vector3 sum = CGAL::NULL_VECTOR;
  for (const Point3& p : clipped) sum = sum + (p - CGAL::ORIGIN);
  const Point3 centre = CGAL::ORIGIN + sum / static_cast<int>(clipped.size());
  for (const Face& face : solid.faces())
    if (plane_value(face.plane, centre) >= 0) return false;
  return true;
}

// returns true when the convex hull of simplex (2 or 3 points) meets solid's interior.
inline bool simplex_meets_interior(std::vector<Point3> polygon, const ConvexPolyhedron& solid) {
  const std::vector<Point3> clipped = clip_to_solid(std::move(polygon), solid);
  return !clipped.empty() && clipped_meets_interior(clipped, solid);
}

// returns true when the convex hull of simplex (2 or 3 points) touches the solid's boundary
// without meeting its interior: from such a point X the light grazes the solid, and X lies
// on the boundary of the solid's blocked set (its shadow volume), where another solid's
// shadow may abut (docs/shadows.md: the lit line between abutting shadows is dropped).
inline bool simplex_grazes(std::vector<Point3> polygon, const ConvexPolyhedron& solid) {
  const std::vector<Point3> clipped = clip_to_solid(std::move(polygon), solid);
  return !clipped.empty() && !clipped_meets_interior(clipped, solid);
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

namespace penumbra::test {

// For a two-sided polygon (no interior) the engine's rule is that a segment is
// blocked when it crosses the polygon's plane at one point strictly inside the
// polygon. This returns true when that holds for the segment from x to some source
// point q1 + t (q2 - q1), t in [0, 1]: each condition is linear in t, so the set of
// such t is an exact interval.
inline bool flat_blocks_some(const Point3& x, const Point3& q1, const Point3& q2,
                             const ConvexPolyhedron& polygon) {
  Exact low = 0, high = 1;
  bool low_open = false, high_open = false;
  // requires f0 + t (f1 - f0) > 0
  auto positive = [&](const Exact& f0, const Exact& f1) {
    if (f0 == f1) {
      if (f0 <= 0) high = -1;  // infeasible
      return;
    }
    const Exact root = f0 / (f0 - f1);
    if (f1 > f0) {
      if (root > low || (root == low && !low_open)) low = root, low_open = true;
    } else {
      if (root < high || (root == high && !high_open)) high = root, high_open = true;
    }
  };
  const Face& face = polygon.faces().front();
  const Exact fx = plane_value(face.plane, x);
  if (fx == 0) return false;
  // The source point strictly on the other side of the plane.
  const Exact s = fx > 0 ? Exact(-1) : Exact(1);
  positive(s * plane_value(face.plane, q1), s * plane_value(face.plane, q2));
  // The source point strictly inside the pyramid from x through the polygon.
  const auto& v = face.vertices;
  const std::size_t n = v.size();
  const CGAL::Orientation inside = CGAL::orientation(x, v[0], v[1], v[2]);
  const Exact sign = inside == CGAL::POSITIVE ? Exact(1) : Exact(-1);
  auto orient = [&](const Point3& a, const Point3& b, const Point3& q) {
    return CGAL::cross_product(a - x, b - x) * (q - x);
  };
  for (std::size_t k = 0; k < n; ++k)
    positive(sign * orient(v[k], v[(k + 1) % n], q1), sign * orient(v[k], v[(k + 1) % n], q2));
  return low < high || (low == high && !low_open && !high_open);
}

// returns true when some segment from x to the source q1q2 is blocked by solid.
inline bool source_partly_blocked(const Point3& x, const Point3& q1, const Point3& q2,
                                  const ConvexPolyhedron& solid) {
  return solid.is_flat() ? flat_blocks_some(x, q1, q2, solid) : triangle_blocked(x, q1, q2, solid);
}

// returns true when the segment from x to q is blocked by solid.
inline bool point_blocked(const Point3& x, const Point3& q, const ConvexPolyhedron& solid) {
  return solid.is_flat() ? flat_blocks_some(x, q, q, solid) : segment_meets_interior(x, q, solid);
}

}  // namespace penumbra::test
