// Dobashi 1995 section 3.3: sigma factors (eq. 13) and the Gibbs ripples they damp.

#include "penumbra/basis/sigma_factors.h"

#include <boost/test/unit_test.hpp>
#include <cmath>

#include "exact_integrals.h"
#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/legendre_series.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra;
using namespace penumbra::basis;
using penumbra::test::moment_of_legendre;

BOOST_AUTO_TEST_SUITE(sigma_factors_suite)

BOOST_AUTO_TEST_CASE(values_of_eq_13) {
  BOOST_TEST(sigma_factor(8, 0) == 1.0);
  // t = pi l / 9 for N = 8.
  BOOST_TEST(sigma_factor(8, 1) == std::sin(pi / 9) / (pi / 9), tt::tolerance(1e-15));
  BOOST_TEST(sigma_factor(8, 8) == std::sin(8 * pi / 9) / (8 * pi / 9), tt::tolerance(1e-15));
  // The factor vanishes at the first neglected degree N + 1, the ripples' frequency.
  BOOST_TEST(std::abs(sigma_factor(8, 9)) < 1e-16);
  const std::vector<double> factors = sigma_factors(8);
  BOOST_TEST_REQUIRE(factors.size() == 9u);
  for (int l = 1; l <= 8; ++l) {
    BOOST_TEST(factors[l] < factors[l - 1]);
    BOOST_TEST(factors[l] > 0);
  }
}

BOOST_AUTO_TEST_CASE(is_the_mean_of_a_mode_over_one_period_of_degree_n_plus_1) {
  // Hamming's derivation: averaging cos(l x) over a window of one period of degree
  // N + 1, width 2 pi / (N + 1), multiplies it by sigma(N, l). Checked by quadrature.
  const int degree = 8;
  const double half_width = pi / (degree + 1), x = 0.37;
  const QuadratureRule rule = mapped(gauss_legendre(40), x - half_width, x + half_width);
  for (int l = 0; l <= degree; ++l) {
    double mean = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      mean += rule.weights[i] * std::cos(l * rule.nodes[i]);
    mean /= 2 * half_width;
    BOOST_TEST(std::abs(mean - sigma_factor(degree, l) * std::cos(l * x)) <= 1e-14, "l " << l);
  }
}

BOOST_AUTO_TEST_CASE(damp_the_ripples_of_the_spot_of_section_3_3_1) {
  // k = 10, spread 90 deg, N = 8 (the paper's Fig. 3): the series rings beyond 90 deg
  // where the spot is dark. Weights exact (exact_integrals.h).
  std::vector<double> weights;
  for (int l = 0; l <= 8; ++l) weights.push_back((2 * l + 1) / 2.0 * moment_of_legendre(10, l));
  const LegendreSeries plain(weights);
  const LegendreSeries smoothed = plain.sigma_smoothed();
  for (int l = 0; l <= 8; ++l)
    BOOST_TEST(smoothed.weights()[l] == sigma_factor(8, l) * weights[l], tt::tolerance(1e-15));
  double plain_ripple = 0, smoothed_ripple = 0, plain_undershoot = 0, smoothed_undershoot = 0;
  for (int i = 0; i <= 1800; ++i) {
    const double g = i * pi / 1800;
    if (g > pi / 2) {
      plain_ripple = std::max(plain_ripple, std::abs(plain(g)));
      smoothed_ripple = std::max(smoothed_ripple, std::abs(smoothed(g)));
    }
    plain_undershoot = std::min(plain_undershoot, plain(g));
    smoothed_undershoot = std::min(smoothed_undershoot, smoothed(g));
  }
  BOOST_TEST_MESSAGE("ripple beyond 90 deg: plain " << plain_ripple << ", sigma "
                                                    << smoothed_ripple);
  BOOST_TEST(smoothed_ripple < plain_ripple / 3);
  BOOST_TEST(smoothed_undershoot > plain_undershoot);
  // The flux is unchanged: sigma(N, 0) = 1.
  BOOST_TEST(smoothed.flux() == plain.flux());
}

BOOST_AUTO_TEST_SUITE_END()
