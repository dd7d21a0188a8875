// The grid that finds the occluders whose whole shadows' boxes may hold a point of the sweep
// (src/shadow/box_grid.h) against testing every box: for random boxes and queries (fixed
// seed), many of them degenerate (points, segments), sharing edges or corners with the
// query, spanning the whole grid or lying outside it, under both rounding modes the sweep
// asks in, the grid returns exactly the boxes that meet the query, in increasing order.

#include <boost/test/unit_test.hpp>

#include <CGAL/FPU.h>

#include <random>

#include "box_grid.h"

using penumbra::Interval;
using penumbra::detail::BoxGrid;

namespace {

using Box = std::array<Interval, 2>;

// the indices of the boxes that meet the closed box at, by testing each.
std::vector<std::size_t> meeting(const std::vector<Box>& boxes, const Box& at) {
  std::vector<std::size_t> result;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    bool meets = true;
    for (int axis = 0; axis < 2; ++axis)
      meets =
          meets && boxes[k][axis].inf() <= at[axis].sup() && at[axis].inf() <= boxes[k][axis].sup();
    if (meets) result.push_back(k);
  }
  return result;
}

// a random interval: on a coarse lattice (so that ends coincide often), a point a quarter of
// the time, up to a fifth of the range wide, and now and then the whole range or beyond it.
Interval random_interval(std::mt19937& random) {
  std::uniform_int_distribution<int> lattice(-40, 140), kind(0, 19), width(0, 20);
  const double low = lattice(random) / 4.0;
  switch (kind(random)) {
    case 0:
      return Interval(-60, 60);
    case 1:
      return Interval(low + 200, low + 201);
    case 2:
    case 3:
    case 4:
    case 5:
    case 6:
      return Interval(low);
    default:
      return Interval(low, low + width(random) / 4.0);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(box_grid)

BOOST_AUTO_TEST_CASE(finds_exactly_the_boxes_that_meet_the_query) {
  std::mt19937 random(20261206);
  std::size_t checked = 0, found = 0;
  for (std::size_t count : {0, 1, 2, 7, 50, 400, 3000}) {
    std::vector<Box> boxes;
    for (std::size_t k = 0; k < count; ++k)
      boxes.push_back({random_interval(random), random_interval(random)});
    const BoxGrid grid(boxes);
    std::vector<std::size_t> out;
    for (int q = 0; q < 400; ++q) {
      Box at{random_interval(random), random_interval(random)};
      if (q % 5 == 0 && !boxes.empty()) {
        // a corner or an edge of a box, exactly
        const Box& box = boxes[random() % boxes.size()];
        at = {Interval(q % 10 ? box[0].sup() : box[0].inf()), box[1]};
      }
      if (q % 2) {
        CGAL::Protect_FPU_rounding<true> upward;  // as the sweep's interval filters ask
        grid.query(at, out);
      } else {
        grid.query(at, out);
      }
      const std::vector<std::size_t> expected = meeting(boxes, at);
      BOOST_TEST(out == expected, "count " << count << " query " << q);
      ++checked;
      found += expected.size();
    }
  }
  BOOST_TEST(checked == 2800u);
  BOOST_TEST(found > 20000u);  // (the queries meet boxes often: the comparisons are not vacuous)
}

BOOST_AUTO_TEST_SUITE_END()
