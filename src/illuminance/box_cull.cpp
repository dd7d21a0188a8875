#include "box_cull.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::illuminance::detail {

Box box_of(const CGAL::Bbox_3& box) {
  return {{box.xmin(), box.ymin(), box.zmin()}, {box.xmax(), box.ymax(), box.zmax()}};
}

Box box_of(std::initializer_list<const Vec3d*> points) {
  Box box{**points.begin(), **points.begin()};
  for (const Vec3d* p : points)
    for (int i = 0; i < 3; ++i) {
      box.low[i] = std::min(box.low[i], (*p)[i]);
      box.high[i] = std::max(box.high[i], (*p)[i]);
    }
  return box;
}

bool overlap(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i)
    if (a.high[i] < b.low[i] || b.high[i] < a.low[i]) return false;
  return true;
}

bool ray_may_meet(const Box& box, const Vec3d& origin, const Vec3d& direction) {
  double t_low = 0, t_high = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double margin =
        1e-9 * (1 + std::abs(box.low[i]) + std::abs(box.high[i]) + std::abs(origin[i]));
    const double low = box.low[i] - margin, high = box.high[i] + margin;
    if (direction[i] == 0) {
      if (origin[i] < low || origin[i] > high) return false;
      continue;
    }
    double t0 = (low - origin[i]) / direction[i], t1 = (high - origin[i]) / direction[i];
    if (t0 > t1) std::swap(t0, t1);
    t_low = std::max(t_low, t0);
    t_high = std::min(t_high, t1);
    if (t_low > t_high) return false;
  }
  return true;
}

BoxGrid::BoxGrid(const std::vector<Box>& boxes, const std::vector<std::size_t>& members) {
  if (members.empty()) return;
  bounds_ = boxes[members.front()];
  for (std::size_t k : members)
    for (int i = 0; i < 3; ++i) {
      bounds_.low[i] = std::min(bounds_.low[i], boxes[k].low[i]);
      bounds_.high[i] = std::max(bounds_.high[i], boxes[k].high[i]);
    }
  // About two cells per member, shaped like the bounds.
  const double target = 2.0 * static_cast<double>(members.size());
  std::array<double, 3> extent;
  double volume = 1;
  int dimensions = 0;
  for (int i = 0; i < 3; ++i) {
    extent[i] = bounds_.high[i] - bounds_.low[i];
    if (extent[i] > 0) {
      volume *= extent[i];
      ++dimensions;
    }
  }
  const double side = dimensions ? std::pow(volume / target, 1.0 / dimensions) : 1;
  for (int i = 0; i < 3; ++i) {
    cells_[i] = extent[i] > 0 ? static_cast<int>(std::clamp(extent[i] / side, 1.0, 256.0)) : 1;
    size_[i] = extent[i] > 0 ? extent[i] / cells_[i] : 1;
  }
  buckets_.resize(static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2]);
  for (std::size_t k : members) {
    const auto low = cell(boxes[k].low), high = cell(boxes[k].high);
    for (int x = low[0]; x <= high[0]; ++x)
      for (int y = low[1]; y <= high[1]; ++y)
        for (int z = low[2]; z <= high[2]; ++z) buckets_[index(x, y, z)].push_back(k);
  }
}

const std::vector<std::size_t>& BoxGrid::near(const Vec3d& point) const {
  static const std::vector<std::size_t> none;
  if (buckets_.empty()) return none;
  for (int i = 0; i < 3; ++i)
    if (point[i] < bounds_.low[i] || point[i] > bounds_.high[i]) return none;
  const auto at = cell(point);
  return buckets_[index(at[0], at[1], at[2])];
}

std::array<int, 3> BoxGrid::cell(const Vec3d& x) const {
  std::array<int, 3> at;
  for (int i = 0; i < 3; ++i)
    at[i] = static_cast<int>(
        std::clamp(std::floor((x[i] - bounds_.low[i]) / size_[i]), 0.0, cells_[i] - 1.0));
  return at;
}

}  // namespace penumbra::illuminance::detail
