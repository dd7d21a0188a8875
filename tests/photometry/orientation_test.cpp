// The photometric frame in the world: gamma from the axis, C counter-clockwise about
// the axis seen from behind the lamp (LM-63 type C and EULUMDAT).

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/photometry/orientation.h"
#include "penumbra/photometry/table_distribution.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::photometry;
using penumbra::Vec3d;

BOOST_AUTO_TEST_SUITE(orientation)

BOOST_AUTO_TEST_CASE(downlight_c90_is_counter_clockwise_from_c0_seen_from_above) {
  // Axis down, C0 along +x. Seen from above (+z), counter-clockwise from +x is +y.
  const Vec3d axis{0, 0, -1}, c0{1, 0, 0};
  const auto to_y = photometric_angles(axis, c0, {0, 1, 0});
  BOOST_TEST(degrees(to_y.gamma) == 90.0, tt::tolerance(1e-12));
  BOOST_TEST(degrees(to_y.c) == 90.0, tt::tolerance(1e-12));
  BOOST_TEST(degrees(photometric_angles(axis, c0, {0, -1, 0}).c) == 270.0, tt::tolerance(1e-12));
  BOOST_TEST(photometric_angles(axis, c0, {0, 0, -5}).gamma == 0.0);
  BOOST_TEST(photometric_angles(axis, c0, {0, 0, 1}).gamma == pi, tt::tolerance(1e-15));
  // 45 degrees below the horizon toward -x: gamma 45, C 180.
  const auto down_left = photometric_angles(axis, c0, {-1, 0, -1});
  BOOST_TEST(degrees(down_left.gamma) == 45.0, tt::tolerance(1e-12));
  BOOST_TEST(degrees(down_left.c) == 180.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(world_direction_inverts_photometric_angles) {
  const double r = 1 / std::sqrt(3.0);
  const Vec3d axis{r, r, r};
  const Vec3d c0{1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0};
  for (double g : {0.1, 1.0, 2.0, 3.0})
    for (double c : {0.2, 1.7, 3.5, 6.0}) {
      const auto back = photometric_angles(axis, c0, world_direction(axis, c0, {g, c}));
      BOOST_TEST(back.gamma == g, tt::tolerance(1e-12));
      BOOST_TEST(back.c == c, tt::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(intensity_toward_uses_the_c_planes_of_the_table) {
  // C0-C180 bilateral table: 10 cd in C0, 20 in C90, 30 in C180 at every gamma.
  PhotometricGrid grid;
  grid.horizontal_deg = {0, 90, 180};
  grid.vertical_deg = {0, 180};
  grid.candela = {{10, 10}, {20, 20}, {30, 30}};
  const TableDistribution lid(grid, Interpolation::linear);
  const Vec3d axis{0, 0, -1}, c0{0, 1, 0};  // C0 along +y: C90 is -x (c0 x axis)
  BOOST_TEST(intensity_toward(lid, axis, c0, {0, 1, -1}) == 10.0, tt::tolerance(1e-12));
  BOOST_TEST(intensity_toward(lid, axis, c0, {-1, 0, -1}) == 20.0, tt::tolerance(1e-12));
  BOOST_TEST(intensity_toward(lid, axis, c0, {0, -1, -1}) == 30.0, tt::tolerance(1e-12));
  BOOST_TEST(intensity_toward(lid, axis, c0, {1, 0, -1}) == 20.0,
             tt::tolerance(1e-12));  // C270 = C90
}

BOOST_AUTO_TEST_SUITE_END()
