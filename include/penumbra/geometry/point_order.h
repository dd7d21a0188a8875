#pragma once
// The lexicographic (x, y, z) order of exact points and rings started at their smallest
// point: the canonical forms of vertex lists, faces and rings (docs/geometry.md).

#include <algorithm>
#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra {

inline bool point_less(const Point3& a, const Point3& b) {
  return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
}

// rotates ring (orientation kept) to start at its lexicographically smallest point.
inline void start_at_smallest(std::vector<Point3>& ring) {
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), point_less), ring.end());
}

}  // namespace penumbra
