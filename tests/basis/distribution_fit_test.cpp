// Fitting the photometry layer's distributions: exact weights of the closed forms,
// tables integrated piecewise, the azimuthal average of asymmetric grids, the error
// over the sphere (Parseval), and SH coefficients in the photometric frame.

#include "penumbra/basis/distribution_fit.h"

#include <Eigen/Geometry>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "exact_integrals.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/sh_rotation.h"
#include "penumbra/basis/spherical_harmonics.h"
#include "penumbra/photometry/orientation.h"
#include "penumbra/photometry/table_distribution.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::basis;
using namespace penumbra::photometry;
using penumbra::test::moment_of_legendre;
using penumbra::test::moment_of_legendre_from;

namespace {

std::shared_ptr<const Distribution> make(const char* text) {
  return make_distribution(nlohmann::json::parse(text), SpecContext{"test", "lid", "."});
}

// A smooth asymmetric distribution with exact SH coefficients:
// I = 2 + x + z / 2 in the photometric frame, x = sin g cos C, z = cos g.
class TiltedDistribution final : public Distribution {
 public:
  double intensity(double gamma, double c) const override {
    return 2 + std::sin(gamma) * std::cos(c) + 0.5 * std::cos(gamma);
  }
  double max_intensity() const override { return 2 + std::sqrt(1.25); }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(distribution_fit)

BOOST_AUTO_TEST_CASE(spot_weights_are_exact) {
  // Dobashi eq. (11): 800 cd cos^10, spread 90 deg. w_l = 800 (2l+1)/2 int_0^1 x^10 P_l.
  const auto spot = make(R"({"cos_power": 10, "spread_deg": 90, "candela": 800})");
  const LegendreFit fit = fit_legendre(*spot, 12, false);
  BOOST_TEST(!fit.azimuthal_average);
  for (int l = 0; l <= 12; ++l)
    BOOST_TEST(std::abs(fit.series.weights()[l] -
                        800 * (2 * l + 1) / 2.0 * moment_of_legendre(10, l)) <= 1e-11,
               "l " << l);
  // A narrow spot: the spread angle is a breakpoint.
  const auto narrow = make(R"({"cos_power": 4, "spread_deg": 30, "candela": 100})");
  const LegendreFit narrow_fit = fit_legendre(*narrow, 8, false);
  for (int l = 0; l <= 8; ++l)
    BOOST_TEST(std::abs(narrow_fit.series.weights()[l] -
                        100 * (2 * l + 1) / 2.0 *
                            moment_of_legendre_from(std::cos(radians(30)), 4, l)) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(rms_error_obeys_parseval) {
  // Orthogonality: (1/4 pi) int (I - S_N)^2 dOmega = (1/2) int_-1^1 I^2 dx
  //   - sum_l w_l^2 / (2l + 1); for 800 cos^10 clipped, (1/2) int_0^1 I^2 = 800^2 / 42.
  const auto spot = make(R"({"cos_power": 10, "spread_deg": 90, "candela": 800})");
  for (int degree : {2, 5, 8}) {
    const LegendreFit fit = fit_legendre(*spot, degree, false);
    double mean_square = 800.0 * 800.0 / 42;
    for (int l = 0; l <= degree; ++l) {
      const double w = 800 * (2 * l + 1) / 2.0 * moment_of_legendre(10, l);
      mean_square -= w * w / (2 * l + 1);
    }
    BOOST_TEST(fit.error.rms_cd == std::sqrt(mean_square), tt::tolerance(1e-9));
    BOOST_TEST(fit.error.max_intensity_cd == 800.0);
    BOOST_TEST(fit.error.max_cd >= fit.error.rms_cd);
    BOOST_TEST(fit.error.rms_relative() == fit.error.rms_cd / 800, tt::tolerance(1e-15));
  }
}

BOOST_AUTO_TEST_CASE(sigma_factors_change_the_reported_error) {
  const auto spot = make(R"({"cos_power": 10, "spread_deg": 90, "candela": 800})");
  const LegendreFit fit = fit_legendre(*spot, 8, true);
  BOOST_TEST(fit.sigma);
  // The smoothed series is no longer the L2-best, so its RMS error is larger.
  BOOST_TEST(fit.error.rms_cd > fit.error_without_sigma.rms_cd);
}

BOOST_AUTO_TEST_CASE(polynomial_distributions_are_fitted_exactly) {
  const auto cardioid = make(R"({"cardioid": true, "candela": 300})");
  const LegendreFit fit = fit_legendre(*cardioid, 3, false);
  BOOST_TEST(fit.series.weights()[0] == 150.0, tt::tolerance(1e-14));
  BOOST_TEST(fit.series.weights()[1] == 150.0, tt::tolerance(1e-14));
  BOOST_TEST(fit.error.max_cd <= 1e-12);
  BOOST_TEST(fit.error.rms_cd <= 1e-12);
}

BOOST_AUTO_TEST_CASE(table_weights_match_their_exact_weights) {
  const auto lamp = make(
      R"({"table_deg": [0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160, 170, 180],
          "candela":   [1000, 990, 950, 880, 780, 650, 500, 340, 180, 60, 0, 0, 0, 0, 0, 0, 0, 0, 0]})");
  const DistributionBreakpoints breakpoints = breakpoints_of(*lamp);
  BOOST_TEST(breakpoints.gamma.size() == 19u);
  const LegendreFit fit = fit_legendre(*lamp, 10, false);
  std::vector<double> nodes,
      candela{1000, 990, 950, 880, 780, 650, 500, 340, 180, 60, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i <= 18; ++i) nodes.push_back(radians(10.0 * i));
  for (int l = 0; l <= 10; ++l)
    BOOST_TEST(std::abs(fit.series.weights()[l] -
                        penumbra::test::table_weight(l, nodes, candela)) <= 1e-11,
               "l " << l);
  // The flux of the series (4 pi w_0) is the table's exact flux.
  BOOST_TEST(fit.series.flux() == lamp->flux(), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(asymmetric_grid_fits_its_azimuthal_average) {
  // A quadrant-symmetric grid: C = 0, 30, 90 stored, unfolded to the whole circle.
  PhotometricGrid grid;
  grid.horizontal_deg = {0, 30, 90};
  grid.vertical_deg = {0, 45, 90, 180};
  grid.candela = {{500, 400, 100, 0}, {500, 300, 50, 0}, {500, 100, 0, 0}};
  const TableDistribution table(grid, Interpolation::linear);
  BOOST_TEST_REQUIRE(!is_rotationally_symmetric(table));
  const DistributionBreakpoints breakpoints = breakpoints_of(table);
  BOOST_TEST(breakpoints.c_exact);
  const AxialProfile average = axial_profile(table, breakpoints);
  for (double gamma : {0.2, 0.9, 1.3, 2.0}) {
    // Independent: adaptive Gauss-Kronrod over the whole circle.
    const double reference =
        boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double c) { return table.intensity(gamma, c); }, 0.0, 2 * pi, 20, 1e-13) /
        (2 * pi);
    BOOST_TEST(average(gamma) == reference, tt::tolerance(1e-11));
  }
  const LegendreFit fit = fit_legendre(table, 6, false);
  BOOST_TEST(fit.azimuthal_average);
  const std::vector<double> expected = legendre_weights(average, 6, breakpoints.gamma);
  for (int l = 0; l <= 6; ++l) BOOST_TEST(fit.series.weights()[l] == expected[l]);
  // The error is measured against the full distribution: at least its asymmetry.
  BOOST_TEST(fit.error.max_cd >=
             std::abs(table.intensity(radians(45), 0) - average(radians(45))) - 1e-9);
  BOOST_TEST(fit.series.flux() == table.flux(), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(sh_coefficients_of_an_asymmetric_distribution_aimed_in_the_world) {
  // I = 2 + x + z/2 = 2 sqrt(4 pi) Y_00 + sqrt(4 pi / 3) (Y_11 + Y_10 / 2).
  const TiltedDistribution tilted;
  const Eigen::VectorXd c = sh_coefficients_of(tilted, 3);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(16);
  expected[sh_index(0, 0)] = 2 * std::sqrt(4 * pi);
  expected[sh_index(1, 1)] = std::sqrt(4 * pi / 3);
  expected[sh_index(1, 0)] = 0.5 * std::sqrt(4 * pi / 3);
  BOOST_TEST((c - expected).cwiseAbs().maxCoeff() <= 1e-12);
  // Aimed by an axis and a C = 0 direction, the world coefficients reproduce the
  // photometry layer's intensity_toward.
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.1, -1).normalized();
  const Eigen::Vector3d c0 = axis.unitOrthogonal();
  const Eigen::VectorXd world = rotate_sh(c, photometric_frame(axis, c0));
  std::mt19937 random(21);  // fixed: reproducible directions
  std::normal_distribution<double> normal;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector3d d(normal(random), normal(random), normal(random));
    const double expected_cd = intensity_toward(tilted, {axis.x(), axis.y(), axis.z()},
                                                {c0.x(), c0.y(), c0.z()}, {d.x(), d.y(), d.z()});
    BOOST_TEST(std::abs(evaluate_sh(world, d) - expected_cd) <= 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(axial_sh_coefficients_are_zonal) {
  const auto spot = make(R"({"cos_power": 10, "spread_deg": 90, "candela": 800})");
  const Eigen::VectorXd c = sh_coefficients_of(*spot, 6);
  for (int l = 0; l <= 6; ++l)
    for (int m = -l; m <= l; ++m) {
      const double expected = m == 0 ? std::sqrt(4 * pi / (2 * l + 1)) * 800 * (2 * l + 1) / 2.0 *
                                           moment_of_legendre(10, l)
                                     : 0.0;
      BOOST_TEST(std::abs(c[sh_index(l, m)] - expected) <= 1e-10);
    }
}

BOOST_AUTO_TEST_SUITE_END()
