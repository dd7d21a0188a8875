// The Gauss-Legendre rules: against Boost.Math's tabulated rule and by exactness.

#include "penumbra/base/gauss_legendre.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

using namespace penumbra;

BOOST_AUTO_TEST_SUITE(gauss_legendre_rule)

BOOST_AUTO_TEST_CASE(matches_boost_math_tabulated_rules) {
  // Boost.Math (boost/math/quadrature/gauss.hpp) stores the nonnegative abscissae of
  // its rules, precomputed in high precision, in increasing order.
  const auto check = [](const auto& abscissa, const auto& weights, int points) {
    const QuadratureRule rule = gauss_legendre(points);
    BOOST_TEST_REQUIRE(rule.nodes.size() == static_cast<std::size_t>(points));
    for (std::size_t k = 0; k < abscissa.size(); ++k) {
      const std::size_t i = points / 2 + k;  // our nodes increase from -1
      BOOST_TEST(std::abs(rule.nodes[i] - abscissa[k]) <= 2e-16, "node " << k);
      BOOST_TEST(std::abs(rule.weights[i] - weights[k]) <= 4e-16, "weight " << k);
      BOOST_TEST(rule.nodes[points - 1 - i] == -rule.nodes[i]);
    }
  };
  using boost::math::quadrature::gauss;
  check(gauss<double, 7>::abscissa(), gauss<double, 7>::weights(), 7);
  check(gauss<double, 20>::abscissa(), gauss<double, 20>::weights(), 20);
  check(gauss<double, 30>::abscissa(), gauss<double, 30>::weights(), 30);
}

BOOST_AUTO_TEST_CASE(integrates_polynomials_of_degree_2n_minus_1_exactly) {
  for (int points : {1, 2, 5, 16, 41}) {
    const QuadratureRule rule = gauss_legendre(points);
    for (int k = 0; k <= 2 * points - 1; ++k) {
      double sum = 0;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i)
        sum += rule.weights[i] * std::pow(rule.nodes[i], k);
      const double exact = (k % 2 == 1) ? 0.0 : 2.0 / (k + 1);
      BOOST_TEST(std::abs(sum - exact) <= 1e-14, "points " << points << ", x^" << k);
    }
  }
}

BOOST_AUTO_TEST_CASE(maps_onto_an_interval) {
  const QuadratureRule rule = mapped(gauss_legendre(4), 1.0, 3.0);
  double sum = 0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i)
    sum += rule.weights[i] * std::pow(rule.nodes[i], 7);
  BOOST_TEST(sum == (std::pow(3.0, 8) - 1) / 8, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
