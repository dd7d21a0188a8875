#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/raytrace/anti_aliasing.h"

// Whitted section 3 on images whose area means are known in closed form.

namespace {

using namespace penumbra::raytrace;
using penumbra::Colour;

Colour grey(double value) {
  return {value, value, value};
}

Corners corners_of(const SampleFunction& f, double x, double y, double size) {
  return {f(x, y), f(x + size, y), f(x, y + size), f(x + size, y + size)};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(anti_aliasing)

BOOST_AUTO_TEST_CASE(nearly_equal_corners_are_averaged_without_new_samples) {
  const SampleFunction ramp = [](double x, double y) { return grey(0.5 + 0.01 * x + 0.02 * y); };
  const SquareEstimate estimate =
      adaptive_mean(ramp, 3, 4, 1, corners_of(ramp, 3, 4, 1), AdaptiveOptions{});
  BOOST_TEST(estimate.samples == 0u);
  // The mean of a linear function over the square is its value at the centre.
  BOOST_TEST(std::abs(estimate.mean[0] - (0.5 + 0.01 * 3.5 + 0.02 * 4.5)) < 1e-15);
}

BOOST_AUTO_TEST_CASE(an_edge_is_refined_to_the_area_it_covers) {
  // White where x < 0.3: the mean over the unit square is 0.3. At depth d the squares that
  // straddle the edge are one column 2^-d wide, where averaging corners errs by at most half
  // that column.
  const SampleFunction edge = [](double x, double) { return grey(x < 0.3 ? 1.0 : 0.0); };
  for (int depth : {2, 4, 6}) {
    AdaptiveOptions options;
    options.max_depth = depth;
    const SquareEstimate estimate =
        adaptive_mean(edge, 0, 0, 1, corners_of(edge, 0, 0, 1), options);
    BOOST_TEST(std::abs(estimate.mean[0] - 0.3) <= std::ldexp(0.5, -depth));
    BOOST_TEST(estimate.samples > 0u);
    // Only the straddling column is refined: far fewer samples than the full grid.
    BOOST_TEST(estimate.samples < static_cast<std::size_t>((1 << depth) + 1) * ((1 << depth) + 1));
  }
}

BOOST_AUTO_TEST_CASE(a_small_object_between_the_corners_is_found_only_when_forced) {
  // A disc of radius 0.05 at (0.55, 0.45): no corner sees it, so the corners agree and the
  // pixel would stay black; the small-object guard forces cuts down to squares of its radius,
  // after which ordinary refinement finds its area pi 0.05^2.
  const SampleFunction disc = [](double x, double y) {
    const double dx = x - 0.55, dy = y - 0.45;
    return grey(dx * dx + dy * dy < 0.0025 ? 1.0 : 0.0);
  };
  AdaptiveOptions options;
  options.max_depth = 8;
  const Corners corners = corners_of(disc, 0, 0, 1);
  BOOST_TEST(adaptive_mean(disc, 0, 0, 1, corners, options).mean[0] == 0.0);
  const double area = adaptive_mean(disc, 0, 0, 1, corners, options, 0, 0.05).mean[0];
  using penumbra::pi;
  BOOST_TEST(std::abs(area - pi * 0.0025) < 0.1 * pi * 0.0025);
}

BOOST_AUTO_TEST_SUITE_END()
