#pragma once
// A uniform grid over boxes, to find the few boxes that may hold a point without testing
// every one: the sweep of exact_umbra.cpp asks, at each point it labels, which occluders'
// whole shadows hold it, and a real model puts thousands of occluders in one touching group
// (docs/linear-shadows.md, "Large groups"). A filter only: it decides nothing, the exact
// tests on the boxes it returns do.

#include <array>
#include <cstddef>
#include <vector>

#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

class BoxGrid {
 public:
  BoxGrid() = default;
  // boxes[k] is box k (closed).
  explicit BoxGrid(const std::vector<std::array<Interval, 2>>& boxes);

  // writes to out, in increasing order, the index of every box that meets the closed box at
  // (exactly: the comparisons are on the boxes' doubles), and no other.
  void query(const std::array<Interval, 2>& at, std::vector<std::size_t>& out) const;

 private:
  // the first and last cells spanned by [low, high] along axis, clamped to the grid.
  std::array<std::size_t, 2> cells(int axis, double low, double high) const;

  std::vector<std::array<Interval, 2>> boxes_;
  double origin_[2] = {0, 0}, scale_[2] = {0, 0};  // cell = (x - origin) * scale
  std::size_t size_ = 0;                           // cells per axis
  std::vector<std::vector<std::size_t>> cells_;    // row-major, the boxes meeting each cell
};

}  // namespace penumbra::detail
