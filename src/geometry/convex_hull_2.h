#pragma once
// Exact 2D convex hull (Andrew's monotone chain) over points with their input
// indices; the hull keeps extreme points only (collinear boundary points dropped).

#include <type_traits>
#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra::detail {

// returns the indices of the extreme points of points, counter-clockwise, starting
// at the lexicographically smallest. Returns fewer than 3 indices when all points
// are collinear.
std::vector<int> convex_hull_2(const std::vector<Point2>& points);

// compares directions by the lexicographic (x, y, z) order of their unit vectors,
// exactly (no square roots): a strict weak order whose ties are equal directions. For
// rational vectors, and for interval ones (then the answer may be uncertain).
template <class Vector>
auto direction_less(const Vector& a, const Vector& b) -> decltype(a[0] < b[0]) {
  using Number = std::decay_t<decltype(a.squared_length())>;
  const Number a_length = a.squared_length();
  const Number b_length = b.squared_length();
  for (int i = 0; i < 3; ++i) {
    // sign(a_i) a_i^2 / |a|^2 is monotone in a_i / |a|; cross-multiply the lengths.
    const Number a_square = a[i] * a[i], b_square = b[i] * b[i];
    const Number ka = (a[i] < 0 ? Number(-a_square) : a_square) * b_length;
    const Number kb = (b[i] < 0 ? Number(-b_square) : b_square) * a_length;
    if (ka < kb) return true;
    if (kb < ka) return false;
  }
  return false;
}

// the same for Epeck vectors: decided in intervals when they are certain, in rationals
// otherwise (no lazy construction made).
bool direction_less(const Vector3& a, const Vector3& b);

// returns an in-plane direction for the plane with the given normal.
Vector3 in_plane_direction(const Vector3& normal);

}  // namespace penumbra::detail
