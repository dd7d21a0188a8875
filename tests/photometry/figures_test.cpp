// Derived figures: beam and field angles, maximum, and the partial sphere of
// lighting (Nishita 1985 section 3.1, Fig. 2), against hand derivations.

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/photometry/analytic_distribution.h"
#include "penumbra/photometry/figures.h"
#include "penumbra/photometry/table_distribution.h"
#include "printing.h"

namespace tt = boost::test_tools;
using namespace penumbra::photometry;

BOOST_AUTO_TEST_SUITE(figures)

BOOST_AUTO_TEST_CASE(beam_and_field_angles_of_a_cos_power_spot) {
  // cos^10 g = 0.5 at g = acos(0.5^(1/10)) = 21.0873503 deg: beam 42.1747007 deg;
  // cos^10 g = 0.1 at acos(0.1^(1/10)) = 37.4081483 deg: field 74.8162966 deg.
  const CosPowerDistribution spot(800, 10, 90);
  const Figures figures = compute_figures(spot);
  BOOST_TEST(figures.beam_angle_deg == 42.1747007, tt::tolerance(1e-8));
  BOOST_TEST(figures.field_angle_deg == 74.8162966, tt::tolerance(1e-8));
  BOOST_TEST(figures.max_candela == 800.0);
  BOOST_TEST(figures.symmetry == Symmetry::axial);
}

BOOST_AUTO_TEST_CASE(beam_of_an_off_axis_peak_is_measured_around_the_peak) {
  // Batwing: 100 cd at gamma 40, falling linearly to 0 at 20 and 60: half at 30 and
  // 50, so the beam through the axis is 20 degrees wide.
  const auto batwing =
      make_axial_table({0, 20, 40, 60, 180}, {0, 0, 100, 0, 0}, Interpolation::linear);
  const Figures figures = compute_figures(*batwing);
  BOOST_TEST(figures.beam_planes_deg[0] == 20.0, tt::tolerance(1e-8));
  BOOST_TEST(degrees(figures.max_direction.gamma) == 40.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(partial_sphere_of_a_spot_is_one_sphere) {
  // cos^2 spread 60: dark below I0 / 256 only beyond the spread, so theta_c = 60;
  // r_a = sqrt(I0 / (E_full / 256)) = sqrt(800 * 256 / 500) = 20.2385770 m.
  const CosPowerDistribution spot(800, 2, 60);
  const PartialSphere sphere = partial_sphere(spot);
  BOOST_TEST(sphere.spread_deg == 60.0, tt::tolerance(1e-9));
  BOOST_TEST(!sphere.two_spheres);
  BOOST_TEST(sphere.radius_m == std::sqrt(800.0 * 256 / 500), tt::tolerance(1e-14));
  // A sharper spot reaches 1/256 inside its spread: cos^10 g = 1/256 at acos(2^-0.8).
  const PartialSphere sharp = partial_sphere(CosPowerDistribution(800, 10, 90));
  BOOST_TEST(sharp.spread_deg == degrees(std::acos(std::pow(2.0, -0.8))), tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(partial_sphere_beyond_90_degrees_has_upper_and_lower_radii) {
  // Fig. 2b with I0 (1 + cos g) / 2: I = I0 / 256 at cos g = -127/128, g = 172.8333566;
  // lower radius from I0, upper from the upper hemisphere's maximum, I0 / 2 just above 90.
  const CardioidDistribution lid(1000);
  const PartialSphere sphere = partial_sphere(lid, {1.0 / 256, 100});
  BOOST_TEST(sphere.spread_deg == 172.8333566, tt::tolerance(1e-8));
  BOOST_TEST(sphere.two_spheres);
  BOOST_TEST(sphere.lower_radius_m == std::sqrt(1000.0 * 256 / 100), tt::tolerance(1e-14));
  // sampled at gamma = 90.25 deg: I = 500 (1 - sin 0.25 deg) -> within 0.3%
  BOOST_TEST(sphere.upper_radius_m == std::sqrt(500.0 * 256 / 100), tt::tolerance(3e-3));
}

BOOST_AUTO_TEST_SUITE_END()
