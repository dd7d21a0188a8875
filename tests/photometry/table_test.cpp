// Tabulated distributions: interpolation (linear and Nishita eq. 1), ranges,
// symmetry unfolding, type B mapping and the exact flux of the interpolant.

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/photometry/table_distribution.h"
#include "printing.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::photometry;

namespace {

// Independent flux: the midpoint rule in u = cos(gamma) and C (dOmega = du dC).
double midpoint_flux(const Distribution& lid, int nu = 2000, int nc = 360) {
  double total = 0;
  for (int i = 0; i < nu; ++i) {
    const double gamma = std::acos(1 - (i + 0.5) * 2.0 / nu);
    for (int j = 0; j < nc; ++j) total += lid.intensity(gamma, (j + 0.5) * 2 * pi / nc);
  }
  return total * (2.0 / nu) * (2 * pi / nc);
}

PhotometricGrid c_grid(std::vector<double> h, std::vector<double> v,
                       std::vector<std::vector<double>> candela) {
  PhotometricGrid grid;
  grid.horizontal_deg = std::move(h);
  grid.vertical_deg = std::move(v);
  grid.candela = std::move(candela);
  return grid;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(table_distribution)

BOOST_AUTO_TEST_CASE(linear_interpolation_matches_hand_values) {
  const auto lid = make_axial_table({0, 10, 20}, {100, 50, 0}, Interpolation::linear);
  BOOST_TEST(lid->intensity(radians(5), 0) == 75.0, tt::tolerance(1e-12));
  BOOST_TEST(lid->intensity(radians(15), 2.0) == 25.0, tt::tolerance(1e-12));
  BOOST_TEST(lid->intensity(radians(10), 0) == 50.0);  // a node, exactly
  BOOST_TEST(lid->intensity(radians(20), 0) == 0.0);
  // Beyond the table (20..180 degrees here) the intensity is zero.
  BOOST_TEST(lid->intensity(radians(30), 0) == 0.0);
}

BOOST_AUTO_TEST_CASE(cosine_interpolation_is_nishita_eq_1) {
  // Eq. (1) with t = (cos g - cos g_i) / (cos g_i+1 - cos g_i). By hand:
  //   at 5 deg:  t = (0.99619470 - 1) / (0.98480775 - 1) = 0.25047657, I = 100 - 50 t = 87.476172
  //   at 15 deg: t = (0.96592583 - 0.98480775) / (0.93969262 - 0.98480775) = 0.41852757,
  //              I = 50 - 50 t = 29.073621
  const auto lid = make_axial_table({0, 10, 20}, {100, 50, 0}, Interpolation::cosine);
  BOOST_TEST(lid->intensity(radians(5), 0) == 87.476172, tt::tolerance(1e-7));
  BOOST_TEST(lid->intensity(radians(15), 0) == 29.073621, tt::tolerance(1e-7));
  BOOST_TEST(lid->intensity(radians(10), 0) == 50.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(cosine_interpolation_error_is_largest_near_the_axis) {
  // docs/photometry.md: on a 10-degree table the two t differ by 0.2495 in the middle
  // of the first interval; elsewhere by about (delta / 8) cot(g) at the middle of an
  // interval, delta the step in radians: at 45 degrees (0.174533 / 8) * 1 = 0.021817.
  const auto linear = make_axial_table({0, 10, 40, 50}, {1, 0, 1, 0}, Interpolation::linear);
  const auto cosine = make_axial_table({0, 10, 40, 50}, {1, 0, 1, 0}, Interpolation::cosine);
  BOOST_TEST(
      std::fabs(linear->intensity(radians(5), 0) - cosine->intensity(radians(5), 0)) == 0.2495234,
      tt::tolerance(1e-5));
  BOOST_TEST(
      std::fabs(linear->intensity(radians(45), 0) - cosine->intensity(radians(45), 0)) == 0.021817,
      tt::tolerance(0.01));
}

BOOST_AUTO_TEST_CASE(flux_of_a_constant_table_is_four_pi_i) {
  const auto lid = make_axial_table({0, 180}, {100, 100}, Interpolation::linear);
  BOOST_TEST(lid->flux() == 4 * pi * 100, tt::tolerance(1e-12));
  BOOST_TEST(lid->intensity(pi, 1.0) == 100.0);  // pi itself, not radians(180), hits the end
}

BOOST_AUTO_TEST_CASE(flux_of_a_ramp_matches_the_hand_integral) {
  // I = 100 (1 - 2 g / pi) on 0..90, 0 beyond: 2 pi 100 int (1 - 2g/pi) sin g dg
  //   = 2 pi 100 (1 - 2/pi), since int_0^pi/2 g sin g dg = 1.
  const auto lid = make_axial_table({0, 90, 180}, {100, 0, 0}, Interpolation::linear);
  BOOST_TEST(lid->flux() == 2 * pi * 100 * (1 - 2 / pi), tt::tolerance(1e-12));
  // The cosine interpolant is linear in u = cos g: 2 pi 100 int_0^1 u du = 100 pi.
  const auto cosine = make_axial_table({0, 90, 180}, {100, 0, 0}, Interpolation::cosine);
  BOOST_TEST(cosine->flux() == 100 * pi, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(flux_of_the_paper_curve_matches_an_independent_quadrature) {
  const std::vector<double> angles{0,   10,  20,  30,  40,  50,  60,  70,  80, 90,
                                   100, 110, 120, 130, 140, 150, 160, 170, 180};
  const std::vector<double> candela{1000, 990, 950, 880, 780, 650, 500, 340, 180, 60,
                                    0,    0,   0,   0,   0,   0,   0,   0,   0};
  for (auto interpolation : {Interpolation::linear, Interpolation::cosine}) {
    const auto lid = make_axial_table(angles, candela, interpolation);
    BOOST_TEST(lid->flux() == midpoint_flux(*lid), tt::tolerance(1e-5));
  }
}

BOOST_AUTO_TEST_CASE(quadrant_grid_unfolds_into_four_mirrored_quarters) {
  TableDistribution lid(c_grid({0, 45, 90}, {0, 90}, {{10, 1}, {20, 2}, {30, 3}}),
                        Interpolation::linear);
  BOOST_TEST(lid.symmetry() == Symmetry::quadrant);
  for (double c : {0.0, 20.0, 45.0, 70.0, 90.0}) {
    const double value = lid.intensity(radians(40), radians(c));
    BOOST_TEST(lid.intensity(radians(40), radians(180 - c)) == value, tt::tolerance(1e-12));
    BOOST_TEST(lid.intensity(radians(40), radians(180 + c)) == value, tt::tolerance(1e-12));
    BOOST_TEST(lid.intensity(radians(40), radians(360 - c)) == value, tt::tolerance(1e-12));
  }
  BOOST_TEST(lid.intensity(0, radians(135)) == 20.0);
  BOOST_TEST(lid.max_intensity() == 30.0);
  BOOST_TEST(degrees(lid.max_direction().c) == 90.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(bilateral_grids_mirror_about_their_own_plane) {
  TableDistribution c0(c_grid({0, 90, 180}, {0, 90}, {{10, 1}, {20, 2}, {30, 3}}),
                       Interpolation::linear);
  BOOST_TEST(c0.symmetry() == Symmetry::bilateral_c0_c180);
  BOOST_TEST(c0.intensity(0, radians(270)) == 20.0);  // C270 = C90
  BOOST_TEST(c0.intensity(0, radians(300)) == c0.intensity(0, radians(60)), tt::tolerance(1e-12));
  TableDistribution c90(c_grid({90, 180, 270}, {0, 90}, {{10, 1}, {20, 2}, {30, 3}}),
                        Interpolation::linear);
  BOOST_TEST(c90.symmetry() == Symmetry::bilateral_c90_c270);
  BOOST_TEST(c90.intensity(0, 0) == 20.0);  // C0 = C180
  BOOST_TEST(c90.intensity(0, radians(30)) == c90.intensity(0, radians(150)), tt::tolerance(1e-12));
  BOOST_TEST(c90.intensity(0, radians(315)) == c90.intensity(0, radians(225)),
             tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(azimuth_360_is_azimuth_0_not_zero) {
  // The bug of other parsers: C = 360 (or beyond the last plane) fell off the table.
  TableDistribution full(c_grid({0, 120, 240, 360}, {0, 180}, {{5, 5}, {6, 6}, {7, 7}, {5, 5}}),
                         Interpolation::linear);
  BOOST_TEST(full.intensity(1.0, radians(360)) == 5.0, tt::tolerance(1e-12));
  BOOST_TEST(full.intensity(1.0, 2 * pi) == 5.0, tt::tolerance(1e-12));
  // Without the closing plane the circle closes on C = 0: at 300, halfway 240..360.
  TableDistribution open(c_grid({0, 120, 240}, {0, 180}, {{5, 5}, {6, 6}, {7, 7}}),
                         Interpolation::linear);
  BOOST_TEST(open.intensity(1.0, radians(300)) == 6.0, tt::tolerance(1e-12));
  BOOST_TEST(open.intensity(1.0, radians(-60)) == 6.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(gamma_range_90_180_is_dark_below_the_horizon) {
  TableDistribution up(c_grid({0}, {90, 135, 180}, {{0, 50, 100}}), Interpolation::linear);
  BOOST_TEST(up.intensity(radians(45), 0) == 0.0);
  BOOST_TEST(up.intensity(radians(157.5), 0) == 75.0, tt::tolerance(1e-12));
  // 2 pi int_pi/2^pi of the ramp: checked against the quadrature.
  BOOST_TEST(up.flux() == midpoint_flux(up), tt::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(type_b_maps_the_beam_axis_to_gamma_0) {
  // Type B: lateral angle H (blocks) and plane tilt V (values). The direction
  // (cos H sin V, sin H, cos H cos V) in (c0, c90, axis): H = 90 is C = 90, gamma = 90;
  // V = 90 at H = 0 is C = 0, gamma = 90.
  PhotometricGrid grid;
  grid.type = PhotometricType::b;
  grid.horizontal_deg = {-90, 0, 90};
  grid.vertical_deg = {-90, 0, 90};
  grid.candela = {{7, 7, 7}, {1, 100, 3}, {9, 9, 9}};
  TableDistribution lid(grid, Interpolation::linear);
  BOOST_TEST(lid.intensity(0, 0) == 100.0, tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(pi / 2, 0) == 3.0, tt::tolerance(1e-12));       // V = +90
  BOOST_TEST(lid.intensity(pi / 2, pi) == 1.0, tt::tolerance(1e-12));      // V = -90
  BOOST_TEST(lid.intensity(pi / 2, pi / 2) == 9.0, tt::tolerance(1e-12));  // H = +90
  BOOST_TEST(lid.intensity(pi / 2, 1.5 * pi) == 7.0, tt::tolerance(1e-12));
  // The back hemisphere is outside -90..90 of V: dark.
  BOOST_TEST(lid.intensity(2.5, 0.3) == 0.0);
  // Flux: the exact integral in (H, V) with dOmega = cos H dH dV against the quadrature.
  BOOST_TEST(lid.flux() == midpoint_flux(lid, 2000, 720), tt::tolerance(2e-4));
}

BOOST_AUTO_TEST_CASE(type_a_maps_the_beam_axis_to_gamma_0) {
  PhotometricGrid grid;
  grid.type = PhotometricType::a;
  grid.horizontal_deg = {0, 45, 90};  // laterally symmetric
  grid.vertical_deg = {-90, 0, 90};
  grid.candela = {{1, 100, 3}, {1, 50, 3}, {1, 10, 3}};
  TableDistribution lid(grid, Interpolation::linear);
  BOOST_TEST(lid.symmetry() == Symmetry::bilateral_c0_c180);
  BOOST_TEST(lid.intensity(0, 0) == 100.0, tt::tolerance(1e-12));
  BOOST_TEST(lid.intensity(pi / 4, pi / 2) == 50.0, tt::tolerance(1e-12));    // H = 45
  BOOST_TEST(lid.intensity(pi / 4, 1.5 * pi) == 50.0, tt::tolerance(1e-12));  // H = -45
  BOOST_TEST(lid.flux() == midpoint_flux(lid, 2000, 720), tt::tolerance(2e-4));
}

BOOST_AUTO_TEST_CASE(horizontal_ranges_follow_lm63) {
  using V = std::vector<double>;
  BOOST_TEST((horizontal_symmetry(V{0}, PhotometricType::c) == Symmetry::axial));
  BOOST_TEST((horizontal_symmetry(V{0, 45, 90}, PhotometricType::c) == Symmetry::quadrant));
  BOOST_TEST((horizontal_symmetry(V{0, 180}, PhotometricType::c) == Symmetry::bilateral_c0_c180));
  BOOST_TEST((horizontal_symmetry(V{90, 270}, PhotometricType::c) == Symmetry::bilateral_c90_c270));
  BOOST_TEST((horizontal_symmetry(V{0, 90, 180, 270, 360}, PhotometricType::c) == Symmetry::none));
  BOOST_TEST(!horizontal_symmetry(V{0, 45}, PhotometricType::c));
  BOOST_TEST(!horizontal_symmetry(V{10, 100}, PhotometricType::c));
}

BOOST_AUTO_TEST_SUITE_END()
