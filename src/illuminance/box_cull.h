#pragma once
// Bounding-box culls of the illuminance solver (private). They only skip exact tests that
// cannot find a blocker: every box is closed and rounded outward, so touching counts as
// meeting.

#include <array>
#include <cstddef>
#include <initializer_list>
#include <vector>

#include <CGAL/Bbox_3.h>

#include "penumbra/base/vec3d.h"

namespace penumbra::illuminance::detail {

struct Box {
  Vec3d low;
  Vec3d high;
};

Box box_of(const CGAL::Bbox_3& box);

// the box of a few points given as doubles (exact: no arithmetic).
Box box_of(std::initializer_list<const Vec3d*> points);

bool overlap(const Box& a, const Box& b);

// returns false only when the ray origin + t direction, t >= 0, certainly misses box.
// A slab test in doubles on a box widened by 1e-9 of the coordinates' magnitude, far
// more than the rounding of the slab parameters (a few ulps of |t|), so no ray that
// meets the true box is dropped.
bool ray_may_meet(const Box& box, const Vec3d& origin, const Vec3d& direction);

// A uniform grid over boxes, for the containing-object query: the cell of a point lists
// every box that can hold it. Cells are computed from coordinates by one monotone
// expression (a difference and a division, rounded to nearest, then floor), so a point
// inside a box falls in a cell between those of the box's corners: no box that holds the
// point is missed.
class BoxGrid {
 public:
  BoxGrid() = default;
  // indexes boxes[k] for each k in members (increasing).
  BoxGrid(const std::vector<Box>& boxes, const std::vector<std::size_t>& members);

  // returns the members whose box may hold point (increasing), or none.
  const std::vector<std::size_t>& near(const Vec3d& point) const;

 private:
  std::array<int, 3> cell(const Vec3d& x) const;
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x;
  }

  Box bounds_{};
  std::array<int, 3> cells_{1, 1, 1};
  std::array<double, 3> size_{1, 1, 1};
  std::vector<std::vector<std::size_t>> buckets_;
};

}  // namespace penumbra::illuminance::detail
