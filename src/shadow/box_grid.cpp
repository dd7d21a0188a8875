#include "box_grid.h"

#include <algorithm>
#include <cmath>

#include <CGAL/FPU.h>

namespace penumbra::detail {

BoxGrid::BoxGrid(const std::vector<std::array<Interval, 2>>& boxes) : boxes_(boxes) {
  if (boxes_.empty()) return;
  double low[2] = {boxes_[0][0].inf(), boxes_[0][1].inf()};
  double high[2] = {boxes_[0][0].sup(), boxes_[0][1].sup()};
  for (const auto& box : boxes_)
    for (int axis = 0; axis < 2; ++axis) {
      low[axis] = std::min(low[axis], box[axis].inf());
      high[axis] = std::max(high[axis], box[axis].sup());
    }
  // about one box per cell when they are spread out; at most 128 x 128 cells.
  size_ = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(boxes_.size())))), 1, 128);
  for (int axis = 0; axis < 2; ++axis) {
    origin_[axis] = low[axis];
    const double extent = high[axis] - low[axis];
    scale_[axis] = extent > 0 && std::isfinite(extent) ? static_cast<double>(size_) / extent : 0;
  }
  cells_.resize(size_ * size_);
  for (std::size_t k = 0; k < boxes_.size(); ++k) {
    const auto& box = boxes_[k];
    const auto x = cells(0, box[0].inf(), box[0].sup());
    const auto y = cells(1, box[1].inf(), box[1].sup());
    for (std::size_t j = y[0]; j <= y[1]; ++j)
      for (std::size_t i = x[0]; i <= x[1]; ++i) cells_[j * size_ + i].push_back(k);
  }
}

std::array<std::size_t, 2> BoxGrid::cells(int axis, double low, double high) const {
  // One rounding mode for building and asking: the cell of x is then monotone in x.
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  const auto cell = [&](double x) -> std::size_t {
    const double c = std::floor((x - origin_[axis]) * scale_[axis]);
    if (!(c > 0)) return 0;  // (NaN included)
    return std::min(static_cast<std::size_t>(c), size_ - 1);
  };
  return {cell(low), cell(high)};
}

void BoxGrid::query(const std::array<Interval, 2>& at, std::vector<std::size_t>& out) const {
  out.clear();
  if (size_ == 0) return;
  const auto x = cells(0, at[0].inf(), at[0].sup());
  const auto y = cells(1, at[1].inf(), at[1].sup());
  const auto meets = [&](std::size_t k) {
    const auto& box = boxes_[k];
    for (int axis = 0; axis < 2; ++axis)
      if (box[axis].sup() < at[axis].inf() || box[axis].inf() > at[axis].sup()) return false;
    return true;
  };
  for (std::size_t j = y[0]; j <= y[1]; ++j)
    for (std::size_t i = x[0]; i <= x[1]; ++i)
      for (std::size_t k : cells_[j * size_ + i])
        if (meets(k)) out.push_back(k);
  if (x[0] != x[1] || y[0] != y[1]) {
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
}

}  // namespace penumbra::detail
