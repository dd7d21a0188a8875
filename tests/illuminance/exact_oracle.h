#pragma once
// An exact segment-versus-convex-solid test written for the tests, independently of the
// library's occlusion code (which builds shadow pyramids through contours): the open
// segment p -> p + t d, t in (0, t_max), meets the solid's interior iff some t has every
// face plane negative, a one-dimensional clip; for a flat polygon, iff it crosses the
// plane strictly between p and the end at a point strictly inside every edge.

#include <optional>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra::test {

inline Exact evaluate(const Plane3& plane, const Point3& x) {
  return plane.a() * x.x() + plane.b() * x.y() + plane.c() * x.z() + plane.d();
}

// t_max empty: a ray.
inline bool oracle_meets_interior(const ConvexPolyhedron& solid, const Point3& p, const Vector3& d,
                                  const std::optional<Exact>& t_max) {
  if (solid.is_flat()) {
    const Face& face = solid.faces()[0];
    const Exact at_p = evaluate(face.plane, p);
    const Exact rate = face.normal() * d;
    if (rate == 0) return false;
    const Exact t = -at_p / rate;
    if (!(t > 0) || (t_max && !(t < *t_max))) return false;
    const Point3 x = p + t * d;
    const std::size_t n = face.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      // Counter-clockwise seen from outside: the interior is to the left of each edge.
      const Vector3 edge = face.vertices[(i + 1) % n] - face.vertices[i];
      if (!(CGAL::cross_product(edge, x - face.vertices[i]) * face.normal() > 0)) return false;
    }
    return true;
  }
  Exact low = 0;
  std::optional<Exact> high = t_max;
  for (const Face& face : solid.faces()) {
    const Exact at_p = evaluate(face.plane, p);
    const Exact rate = face.normal() * d;
    if (rate == 0) {
      if (!(at_p < 0)) return false;
    } else if (rate > 0) {
      const Exact t = -at_p / rate;
      if (!high || t < *high) high = t;
    } else {
      const Exact t = -at_p / rate;
      if (t > low) low = t;
    }
  }
  return !high || low < *high;
}

// true when the open segment p q meets the solid's interior.
inline bool oracle_segment_blocked(const ConvexPolyhedron& solid, const Point3& p,
                                   const Point3& q) {
  return oracle_meets_interior(solid, p, q - p, Exact(1));
}

}  // namespace penumbra::test
