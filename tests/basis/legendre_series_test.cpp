// Legendre weights of Dobashi 1995 eq. (3) against integrals derived by hand.

#include "penumbra/basis/legendre_series.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "exact_integrals.h"
#include "penumbra/base/numbers.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::basis;
using penumbra::test::moment_of_legendre;
using penumbra::test::moment_of_legendre_from;

BOOST_AUTO_TEST_SUITE(legendre_series)

BOOST_AUTO_TEST_CASE(polynomials_match_the_standard_library_and_closed_forms) {
  for (double x : {-1.0, -0.7, -0.1, 0.0, 0.35, 0.9, 1.0}) {
    const std::vector<double> p = legendre_polynomials(20, x);
    BOOST_TEST(p[2] == (3 * x * x - 1) / 2, tt::tolerance(1e-15));
    BOOST_TEST(std::abs(p[3] - (5 * x * x * x - 3 * x) / 2) <= 1e-15);
    for (int l = 0; l <= 20; ++l)
      BOOST_TEST(std::abs(p[l] - std::legendre(l, x)) <= 1e-14, "l " << l << " x " << x);
  }
}

BOOST_AUTO_TEST_CASE(moment_oracle_agrees_with_its_term_by_term_derivation) {
  // The two closed forms of exact_integrals.h, derived differently, agree.
  for (int n : {0, 1, 2, 5, 10})
    for (int l = 0; l <= 10; ++l)
      BOOST_TEST(std::abs(moment_of_legendre(n, l) - moment_of_legendre_from(0, n, l)) <= 1e-14,
                 "n " << n << " l " << l);
}

BOOST_AUTO_TEST_CASE(cosine_over_the_whole_sphere_is_p1) {
  // I = cos g = P_1(cos g): w_1 = 1 and every other weight 0 (orthogonality).
  const auto w = legendre_weights([](double g) { return std::cos(g); }, 8);
  for (int l = 0; l <= 8; ++l) BOOST_TEST(std::abs(w[l] - (l == 1 ? 1.0 : 0.0)) <= 4e-15);
}

BOOST_AUTO_TEST_CASE(cardioid_has_two_weights) {
  // (1 + cos g) / 2 = P_0 / 2 + P_1 / 2.
  const auto w = legendre_weights([](double g) { return (1 + std::cos(g)) / 2; }, 6);
  BOOST_TEST(w[0] == 0.5, tt::tolerance(1e-15));
  BOOST_TEST(w[1] == 0.5, tt::tolerance(1e-15));
  for (int l = 2; l <= 6; ++l) BOOST_TEST(std::abs(w[l]) <= 2e-15);
}

BOOST_AUTO_TEST_CASE(clipped_cosine_matches_hand_derived_weights) {
  // I = max(cos g, 0): w_l = (2l + 1)/2 int_0^1 x P_l(x) dx, so
  //   w_0 = 1/4, w_1 = 1/2, w_2 = 5/2 * 1/8 = 5/16, w_3 = 0,
  //   w_4 = 9/2 * int_0^1 (35x^5 - 30x^3 + 3x)/8 dx = 9/2 * (35/6 - 30/4 + 3/2)/8 = -3/32.
  const auto w = legendre_weights([](double g) { return std::max(0.0, std::cos(g)); }, 4, {pi / 2});
  const double expected[] = {0.25, 0.5, 5.0 / 16, 0, -3.0 / 32};
  for (int l = 0; l <= 4; ++l) BOOST_TEST(std::abs(w[l] - expected[l]) <= 1e-15, "l " << l);
}

BOOST_AUTO_TEST_CASE(spot_cos_power_clipped_at_90_degrees) {
  // Dobashi eq. (11), k = 10, spread 90 deg: w_l = (2l + 1)/2 int_0^1 x^10 P_l(x) dx.
  for (double k : {1.0, 3.0, 10.0, 37.5}) {
    const auto w = legendre_weights(
        [k](double g) { return g < pi / 2 ? std::pow(std::cos(g), k) : 0.0; }, 16, {pi / 2});
    for (int l = 0; l <= 16; ++l)
      BOOST_TEST(std::abs(w[l] - (2 * l + 1) / 2.0 * moment_of_legendre(k, l)) <= 2e-14,
                 "k " << k << " l " << l);
  }
}

BOOST_AUTO_TEST_CASE(spot_with_a_narrow_spread_uses_its_breakpoint) {
  // cos^10 inside 40 deg, dark outside: w_l = (2l + 1)/2 int_{cos 40}^1 x^10 P_l dx.
  const double spread = 40 * pi / 180;
  const auto spot = [spread](double g) { return g < spread ? std::pow(std::cos(g), 10) : 0.0; };
  const auto w = legendre_weights(spot, 10, {spread});
  const auto unaware = legendre_weights(spot, 10);
  double unaware_error = 0;
  for (int l = 0; l <= 10; ++l) {
    const double exact = (2 * l + 1) / 2.0 * moment_of_legendre_from(std::cos(spread), 10, l);
    BOOST_TEST(std::abs(w[l] - exact) <= 1e-14, "l " << l);
    unaware_error = std::max(unaware_error, std::abs(unaware[l] - exact));
  }
  // Without the breakpoint Gauss-Legendre integrates across the jump: far worse.
  BOOST_TEST(unaware_error > 1e-6);
}

BOOST_AUTO_TEST_CASE(piecewise_linear_table_matches_its_exact_weights) {
  // The paper's Fig. 1-like curve, linear in gamma between 10-degree nodes; the
  // reference integrates each linear piece in closed form (exact_integrals.h).
  const std::vector<double> candela{1000, 990, 950, 880, 780, 650, 500, 340, 180, 60,
                                    0,    0,   0,   0,   0,   0,   0,   0,   0};
  std::vector<double> nodes;
  for (int i = 0; i <= 18; ++i) nodes.push_back(i * 10 * pi / 180);
  const auto table = [&](double g) {
    const double t = g / (10 * pi / 180);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), 17);
    return candela[i] + (t - static_cast<double>(i)) * (candela[i + 1] - candela[i]);
  };
  const int degree = 12;
  const auto w = legendre_weights(table, degree, nodes);
  for (int l = 0; l <= degree; ++l)
    BOOST_TEST(std::abs(w[l] - penumbra::test::table_weight(l, nodes, candela)) <= 1e-11,
               "l " << l);
  // The closed form itself, checked on one piece against Boost.Math's Gauss-Kronrod.
  const double kronrod = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [](double g) { return (3 + 2 * g) * std::legendre(5, std::cos(g)) * std::sin(g); }, 0.2, 1.1,
      5, 1e-12);
  BOOST_TEST(penumbra::test::linear_times_legendre(5, 0.2, 1.1, 3, 2) == kronrod,
             tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(series_evaluates_eq_2_and_its_flux) {
  const LegendreSeries series({0.25, 0.5, 5.0 / 16});
  const double x = 0.3;
  BOOST_TEST(series.at_cosine(x) == 0.25 + 0.5 * x + 5.0 / 16 * (3 * x * x - 1) / 2,
             tt::tolerance(1e-15));
  BOOST_TEST(series(std::acos(x)) == series.at_cosine(x), tt::tolerance(1e-15));
  // The flux of a clipped cosine of 1 cd on axis: 2 pi int_0^1 x dx = pi = 4 pi w_0.
  BOOST_TEST(series.flux() == pi, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(truncated_series_converges_to_the_distribution) {
  // A smooth distribution (exp of cos) converges geometrically.
  const auto smooth = [](double g) { return std::exp(std::cos(g)); };
  double previous = 1e300;
  for (int degree : {2, 4, 8, 12}) {
    const LegendreSeries series(legendre_weights(smooth, degree));
    double worst = 0;
    for (int i = 0; i <= 180; ++i) {
      const double g = i * pi / 180;
      worst = std::max(worst, std::abs(series(g) - smooth(g)));
    }
    BOOST_TEST(worst < previous / 10, "degree " << degree);
    previous = worst;
  }
  BOOST_TEST(previous < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
