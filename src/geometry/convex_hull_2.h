#pragma once
// Exact 2D convex hull (Andrew's monotone chain) over points with their input
// indices; the hull keeps extreme points only (collinear boundary points dropped).

#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra::detail {

// returns the indices of the extreme points of points, counter-clockwise, starting
// at the lexicographically smallest. Returns fewer than 3 indices when all points
// are collinear.
std::vector<int> convex_hull_2(const std::vector<Point2>& points);

// compares directions by the lexicographic (x, y, z) order of their unit vectors,
// exactly (no square roots): a strict weak order whose ties are equal directions.
bool direction_less(const Vector3& a, const Vector3& b);

// returns an in-plane direction for the plane with the given normal.
Vector3 in_plane_direction(const Vector3& normal);

}  // namespace penumbra::detail
