#pragma once
// The one place that names penumbra's exact kernel (DESIGN.md, "Exactness").
// Every decision about where a boundary lies is made with these types: CGAL's
// Epeck kernel, rationals over GMP with interval filters.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "penumbra/base/vec3d.h"

namespace penumbra {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Exact = Kernel::FT;  // exact rational field number
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;
using Plane3 = Kernel::Plane_3;
using Segment3 = Kernel::Segment_3;
using Line3 = Kernel::Line_3;
using Ray3 = Kernel::Ray_3;
using Triangle3 = Kernel::Triangle_3;
using Point2 = Kernel::Point_2;
using Vector2 = Kernel::Vector_2;
using Segment2 = Kernel::Segment_2;

// converts a double triple to the exact point it denotes (each double is a rational).
inline Point3 to_exact(const Vec3d& p) {
  return Point3(p[0], p[1], p[2]);
}
inline Vector3 to_exact_vector(const Vec3d& v) {
  return Vector3(v[0], v[1], v[2]);
}

// rounds an exact point to the nearest doubles.
inline Vec3d to_double(const Point3& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}
inline Vec3d to_double(const Vector3& v) {
  return {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
}

}  // namespace penumbra
