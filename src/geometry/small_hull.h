#pragma once
// The convex hull of a few points given as doubles (a box, a prism, a building: the
// objects of a large scene), by direct search rather than CGAL's incremental hull: every
// plane through three points that has no point strictly on one side is a face's plane, and
// each face is walked around its extreme points. Every decision is an exact orientation
// test: an interval filter, then dyadic arithmetic (dyadic_vector.h) when the interval
// cannot tell, which is the usual case for the coplanar corners of a CAD box.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace penumbra::detail {

// the most points small_hull takes (the search is O(n^4)).
constexpr std::size_t kSmallHullPoints = 12;

// returns the faces of the convex hull of points (distinct, at most kSmallHullPoints, not all
// coplanar), each a cycle of indices into points, counter-clockwise seen from outside, of its
// extreme points only.
std::vector<std::vector<std::size_t>> small_hull(const std::vector<std::array<double, 3>>& points);

}  // namespace penumbra::detail
