#pragma once
// Planes through points given as doubles, computed exactly without lazy constructions
// (geometry/exact.h): the same rational coefficients as CGAL's Plane_3 constructors, found
// in dyadic arithmetic and converted once. The shadow volumes' contour planes (Nishita 1985
// section 3.2) are built this way for every occluder edge.

#include <array>
#include <optional>

#include "penumbra/geometry/kernel.h"

namespace penumbra {

using Double3 = std::array<double, 3>;

// returns the coordinates of p (or v) when each is a double (its interval a single value).
std::optional<Double3> double_coordinates(const Point3& p);
std::optional<Double3> double_coordinates(const Vector3& v);

// returns the plane of CGAL's Plane3(p, q, r), normal (q - p) x (r - p), turned (every
// coefficient negated) when inside lies on its positive side; nothing when p, q, r are
// collinear.
std::optional<Plane3> oriented_plane(const Double3& p, const Double3& q, const Double3& r,
                                     const Double3& inside);

// returns the plane of CGAL's Plane3(p, cross_product(q - p, direction)), turned likewise;
// nothing when q - p and direction are parallel.
std::optional<Plane3> oriented_plane_along(const Double3& p, const Double3& q,
                                           const Double3& direction, const Double3& inside);

}  // namespace penumbra
