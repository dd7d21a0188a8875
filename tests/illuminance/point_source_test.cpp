#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/point_source.h"
#include "reference_quadrature.h"

namespace {

using penumbra::Vec3d;
using penumbra::illuminance::directional_illuminance;
using penumbra::illuminance::point_illuminance;

using penumbra::pi;

bool close(double value, double expected, double relative) {
  return std::abs(value - expected) <= relative * std::abs(expected);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(point_source)

BOOST_AUTO_TEST_CASE(follows_the_inverse_square_cosine_law) {
  // Lamp at (1, 2, 3) over the origin of the floor: r^2 = 14 and cos(alpha) = 3 / sqrt(14),
  // so eq. (2) gives E = I * 3 / 14^(3/2).
  const double e = point_illuminance({0, 0, 0}, {0, 0, 1}, {1, 2, 3}, 100);
  BOOST_TEST(close(e, 100 * 3 / std::pow(14.0, 1.5), 1e-15));
  // The same geometry on a tilted face: N = (1, 0, 1)/sqrt(2), cos(alpha) = (1 + 3) /
  // (sqrt(2) sqrt(14)).
  const double s = 1 / std::sqrt(2.0);
  const double tilted = point_illuminance({0, 0, 0}, {s, 0, s}, {1, 2, 3}, 100);
  BOOST_TEST(close(tilted, 100 * (4 / (std::sqrt(2.0) * std::sqrt(14.0))) / 14, 1e-15));
}

BOOST_AUTO_TEST_CASE(gives_zero_unless_the_lamp_is_strictly_outside) {
  // Behind the face, in its plane (grazing: the documented tie-break), and at the point.
  BOOST_TEST(point_illuminance({0, 0, 0}, {0, 0, 1}, {1, 2, -3}, 100) == 0.0);
  BOOST_TEST(point_illuminance({0, 0, 0}, {0, 0, 1}, {1, 2, 0}, 100) == 0.0);
  BOOST_TEST(point_illuminance({0, 0, 0}, {0, 0, 1}, {0, 0, 0}, 100) == 0.0);
}

BOOST_AUTO_TEST_CASE(asks_the_distribution_for_the_direction_from_lamp_to_point) {
  Vec3d seen{0, 0, 0};
  int calls = 0;
  const double e = point_illuminance({3, 4, 0}, {0, 0, 1}, {0, 0, 12}, [&](const Vec3d& dir) {
    seen = dir;
    ++calls;
    return 26.0;
  });
  // r = 13: the unit direction is (3, 4, -12) / 13, E = 26 * (12 / 13) / 169.
  BOOST_TEST(calls == 1);
  BOOST_TEST(close(seen[0], 3.0 / 13, 1e-15));
  BOOST_TEST(close(seen[1], 4.0 / 13, 1e-15));
  BOOST_TEST(close(seen[2], -12.0 / 13, 1e-15));
  BOOST_TEST(close(e, 26.0 * 12 / 13 / 169, 1e-15));
  // Facing away: the distribution is not consulted at all.
  point_illuminance({3, 4, 0}, {0, 0, -1}, {0, 0, 12}, [&](const Vec3d&) {
    ++calls;
    return 1.0;
  });
  BOOST_TEST(calls == 1);
}

// CIE 171:2006, test case 5.2: a point source with I(theta) = 1000 cos(theta) cd (theta from
// the downward axis; nothing above the horizontal), H = 3 m above the centre of a 4 m x 4 m
// horizontal surface. With the point at horizontal distance rho from the nadir, r^2 = H^2 +
// rho^2 and cos(theta) = cos(alpha) = H / r, so
//     E = 1000 (H / r) (H / r) / r^2 = 1000 H^2 / (H^2 + rho^2)^2 lux:
// 111.11 lx at the centre, 9000/169 = 53.25 lx at the edge midpoints, 9000/289 = 31.14 lx
// at the corners.
BOOST_AUTO_TEST_CASE(cie_171_test_5_2_cosine_source_over_a_square) {
  const double height = 3;
  const Vec3d lamp{2, 2, height};
  const Vec3d axis{0, 0, -1};
  auto cosine_source = [&](const Vec3d& dir) {
    const double cos_theta = dir[0] * axis[0] + dir[1] * axis[1] + dir[2] * axis[2];
    return cos_theta > 0 ? 1000 * cos_theta : 0.0;
  };
  BOOST_TEST(
      close(point_illuminance({2, 2, 0}, {0, 0, 1}, lamp, cosine_source), 1000.0 / 9, 1e-14));
  for (const Vec3d& corner : {Vec3d{0, 0, 0}, Vec3d{4, 0, 0}, Vec3d{0, 4, 0}, Vec3d{4, 4, 0}})
    BOOST_TEST(
        close(point_illuminance(corner, {0, 0, 1}, lamp, cosine_source), 9000.0 / 289, 1e-14));
  for (const Vec3d& middle : {Vec3d{2, 0, 0}, Vec3d{4, 2, 0}, Vec3d{2, 4, 0}, Vec3d{0, 2, 0}})
    BOOST_TEST(
        close(point_illuminance(middle, {0, 0, 1}, lamp, cosine_source), 9000.0 / 169, 1e-14));
  // Every point of a 0.5 m grid against the formula.
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double x = 0.5 * i, y = 0.5 * j;
      const double rho2 = (x - 2) * (x - 2) + (y - 2) * (y - 2);
      const double expected = 1000 * height * height / std::pow(height * height + rho2, 2);
      BOOST_TEST(
          close(point_illuminance({x, y, 0}, {0, 0, 1}, lamp, cosine_source), expected, 1e-14));
    }
}

BOOST_AUTO_TEST_CASE(directional_light_scales_with_the_cosine) {
  // The scene file's sun: travel (-0.3, -0.2, -0.93); on the floor cos(alpha) = 0.93 / |t|.
  const Vec3d travel{-0.3, -0.2, -0.93};
  const double length = std::sqrt(0.09 + 0.04 + 0.93 * 0.93);
  BOOST_TEST(
      close(directional_illuminance({0, 0, 1}, travel, 80000), 80000 * 0.93 / length, 1e-15));
  // A wall facing +x receives it (0.3 / |t|); one facing -x does not; a vertical sun ray
  // grazes a wall (tie-break: zero).
  BOOST_TEST(close(directional_illuminance({1, 0, 0}, travel, 80000), 80000 * 0.3 / length, 1e-15));
  BOOST_TEST(directional_illuminance({-1, 0, 0}, travel, 80000) == 0.0);
  BOOST_TEST(directional_illuminance({1, 0, 0}, {0, 0, -1}, 80000) == 0.0);
}

// Flux conservation: an isotropic source of I cd emits 4 pi I lumen, all of which lands on
// the inner faces of a closed box around it.
BOOST_AUTO_TEST_CASE(flux_into_a_closed_box_equals_four_pi_i) {
  const Vec3d lamp{0.7, 1.1, 1.9};
  const double candela = 250;
  const double flux = penumbra::test::flux_into_box(
      [&](const Vec3d& p, const Vec3d& n) { return point_illuminance(p, n, lamp, candela); },
      {0, 0, 0}, {2, 3, 2.5}, 8, 8);
  BOOST_TEST(close(flux, 4 * pi * candela, 1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
