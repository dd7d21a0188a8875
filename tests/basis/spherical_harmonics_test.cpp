// Real spherical harmonics (Dobashi 1995 section 3.2 and Appendix): orthonormality,
// the addition theorem (eq. 7), known low-order forms, and the zonal coefficients of
// a re-aimed rotationally symmetric lamp (eqs. 8-10).

#include "penumbra/basis/spherical_harmonics.h"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "exact_integrals.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/legendre_series.h"

using penumbra::pi;

namespace tt = boost::test_tools;
using namespace penumbra::basis;

namespace {

// Fixed seed: the same directions on every run, spread over the sphere.
std::vector<Eigen::Vector3d> random_directions(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> directions;
  for (int i = 0; i < count; ++i)
    directions.push_back(
        Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized());
  return directions;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(spherical_harmonics)

BOOST_AUTO_TEST_CASE(indexing) {
  BOOST_TEST(sh_count(8) == 81);
  BOOST_TEST(sh_index(0, 0) == 0);
  BOOST_TEST(sh_index(1, -1) == 1);
  BOOST_TEST(sh_index(8, 8) == 80);
  BOOST_TEST(sh_degree(81) == 8);
  BOOST_TEST(sh_degree(80) == -1);
}

BOOST_AUTO_TEST_CASE(orthonormal_by_exact_product_quadrature) {
  // Y_lm Y_l'm' has degree <= 2N: the product rule of degree 2N integrates it exactly.
  for (int degree : {0, 1, 4, 8, 16}) {
    const SphereQuadrature rule = product_sphere_quadrature(2 * degree);
    const int n = sh_count(degree);
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t i = 0; i < rule.directions.size(); ++i) {
      const Eigen::VectorXd y = real_spherical_harmonics(degree, rule.directions[i]);
      gram.noalias() += rule.weights[i] * y * y.transpose();
    }
    const double error = (gram - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff();
    BOOST_TEST(error <= 1e-12, "degree " << degree << ": " << error);
  }
}

BOOST_AUTO_TEST_CASE(product_rule_integrates_monomials_exactly) {
  // int x^2 dOmega = 4 pi / 3, int x^2 y^2 z^2 dOmega = 4 pi / 105, int z^4 = 4 pi / 5.
  const SphereQuadrature rule = product_sphere_quadrature(6);
  double xx = 0, xyz = 0, z4 = 0, total = 0;
  for (std::size_t i = 0; i < rule.directions.size(); ++i) {
    const Eigen::Vector3d& d = rule.directions[i];
    total += rule.weights[i];
    xx += rule.weights[i] * d.x() * d.x();
    xyz += rule.weights[i] * d.x() * d.x() * d.y() * d.y() * d.z() * d.z();
    z4 += rule.weights[i] * std::pow(d.z(), 4);
  }
  BOOST_TEST(total == 4 * pi, tt::tolerance(1e-14));
  BOOST_TEST(xx == 4 * pi / 3, tt::tolerance(1e-14));
  BOOST_TEST(xyz == 4 * pi / 105, tt::tolerance(1e-13));
  BOOST_TEST(z4 == 4 * pi / 5, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(low_orders_match_their_cartesian_forms) {
  for (const Eigen::Vector3d& d : random_directions(20, 1)) {
    const double x = d.x(), y = d.y(), z = d.z();
    const Eigen::VectorXd v = real_spherical_harmonics(2, 3.5 * d);  // length is ignored
    const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-15; };
    BOOST_TEST(close(v[sh_index(0, 0)], 1 / std::sqrt(4 * pi)));
    const double c1 = std::sqrt(3 / (4 * pi));
    BOOST_TEST(close(v[sh_index(1, -1)], c1 * y));
    BOOST_TEST(close(v[sh_index(1, 0)], c1 * z));
    BOOST_TEST(close(v[sh_index(1, 1)], c1 * x));
    const double c2 = std::sqrt(15 / (4 * pi));
    BOOST_TEST(close(v[sh_index(2, -2)], c2 * x * y));
    BOOST_TEST(close(v[sh_index(2, -1)], c2 * y * z));
    BOOST_TEST(close(v[sh_index(2, 0)], std::sqrt(5 / (16 * pi)) * (3 * z * z - 1)));
    BOOST_TEST(close(v[sh_index(2, 1)], c2 * x * z));
    BOOST_TEST(close(v[sh_index(2, 2)], c2 / 2 * (x * x - y * y)));
  }
}

BOOST_AUTO_TEST_CASE(match_the_standard_library_spherical_legendre_functions) {
  // std::sph_legendre(l, m, theta) is the complex Y_l^m(theta, 0) with the
  // Condon-Shortley phase (-1)^m; ours has no such phase and sqrt(2) for m != 0.
  const int degree = 20;
  for (const Eigen::Vector3d& d : random_directions(10, 2)) {
    const double theta = std::acos(d.z()), phi = std::atan2(d.y(), d.x());
    const Eigen::VectorXd v = real_spherical_harmonics(degree, d);
    for (int l = 0; l <= degree; ++l)
      for (int m = 0; m <= l; ++m) {
        const double complex_part = (m % 2 ? -1.0 : 1.0) * std::sph_legendre(l, m, theta);
        const double expected_cos =
            (m == 0 ? 1.0 : std::sqrt(2.0)) * complex_part * std::cos(m * phi);
        BOOST_TEST(std::abs(v[sh_index(l, m)] - expected_cos) <= 1e-13, "l " << l << " m " << m);
        if (m > 0) {
          const double expected_sin = std::sqrt(2.0) * complex_part * std::sin(m * phi);
          BOOST_TEST(std::abs(v[sh_index(l, -m)] - expected_sin) <= 1e-13);
        }
      }
  }
}

BOOST_AUTO_TEST_CASE(addition_theorem_eq_7) {
  // sum_m Y_lm(a) Y_lm(b) = (2l + 1) / (4 pi) P_l(a . b), P_l from std::legendre.
  const int degree = 30;
  const auto directions = random_directions(12, 3);
  for (std::size_t i = 0; i + 1 < directions.size(); ++i) {
    const Eigen::Vector3d& a = directions[i];
    const Eigen::Vector3d& b = directions[i + 1];
    const Eigen::VectorXd ya = real_spherical_harmonics(degree, a);
    const Eigen::VectorXd yb = real_spherical_harmonics(degree, b);
    for (int l = 0; l <= degree; ++l) {
      double sum = 0;
      for (int m = -l; m <= l; ++m) sum += ya[sh_index(l, m)] * yb[sh_index(l, m)];
      BOOST_TEST(std::abs(sum - (2 * l + 1) / (4 * pi) * std::legendre(l, a.dot(b))) <= 1e-13,
                 "l " << l);
    }
    // a = b: sum_m Y_lm(a)^2 = (2l + 1) / (4 pi), whatever a.
    for (int l = 0; l <= degree; ++l)
      BOOST_TEST(ya.segment(l * l, 2 * l + 1).squaredNorm() == (2 * l + 1) / (4 * pi),
                 tt::tolerance(1e-13));
  }
}

BOOST_AUTO_TEST_CASE(scanned_appendix_normalisation_breaks_the_addition_theorem) {
  // The Appendix's eq. (22) puts sqrt((2l + 1)/(4 pi) (l - |m|)!/(l + |m|)!) before
  // P_l^m cos(m phi) with no sqrt(2): then sum_m Y_lm(a)^2 falls short of (2l + 1)/(4 pi)
  // for l >= 1 (the m != 0 terms are halved), so eq. (7) fails.
  const Eigen::Vector3d a = Eigen::Vector3d(0.3, -0.4, 0.5).normalized();
  const Eigen::VectorXd v = real_spherical_harmonics(3, a);
  for (int l = 1; l <= 3; ++l) {
    double scanned = 0;
    for (int m = -l; m <= l; ++m) scanned += (m == 0 ? 1.0 : 0.5) * std::pow(v[sh_index(l, m)], 2);
    BOOST_TEST(std::abs(scanned - (2 * l + 1) / (4 * pi)) > 1e-3);
  }
}

BOOST_AUTO_TEST_CASE(appendix_eq_23_holds_for_m_at_least_1_without_condon_shortley_phase) {
  // Eq. (23), P_lm = (2l - 1) sqrt(1 - x^2) P_{l-1,m-1} + P_{l-2,m}, checked against
  // std::assoc_legendre (no Condon-Shortley phase; P_{l-2,m} = 0 when m > l - 2). It
  // cannot start the m = 0 column (it would need P_{l-1,-1}), so it is not a complete
  // recurrence; the code uses the normalised three-term recurrences instead.
  for (double x : {-0.8, -0.2, 0.4, 0.95})
    for (int l = 1; l <= 12; ++l)
      for (int m = 1; m <= l; ++m) {
        const double lower = m <= l - 2 ? std::assoc_legendre(l - 2, m, x) : 0.0;
        const double rhs =
            (2 * l - 1) * std::sqrt(1 - x * x) * std::assoc_legendre(l - 1, m - 1, x) + lower;
        BOOST_TEST(
            std::abs(std::assoc_legendre(l, m, x) - rhs) <= 1e-12 * std::max(1.0, std::abs(rhs)),
            "l " << l << " m " << m);
      }
}

BOOST_AUTO_TEST_CASE(re_aimed_series_equals_the_legendre_series_about_the_new_axis) {
  // Eqs. (8)-(10): c_lm = 4 pi / (2l + 1) w_l Y_lm(axis) reproduces
  // sum_l w_l P_l(axis . r) in every direction r.
  const std::vector<double> weights{0.25, 0.5, 5.0 / 16, 0, -3.0 / 32, 0, 0.05, 0.01, -0.02};
  const LegendreSeries series(weights);
  for (const Eigen::Vector3d& axis : random_directions(5, 4)) {
    const Eigen::VectorXd coefficients = zonal_sh_coefficients(weights, axis);
    for (const Eigen::Vector3d& r : random_directions(30, 5))
      BOOST_TEST(std::abs(evaluate_sh(coefficients, r) - series.at_cosine(axis.dot(r))) <= 1e-14);
  }
  // About the z axis only the zonal terms remain, c_l0 = sqrt(4 pi / (2l + 1)) w_l.
  const Eigen::VectorXd about_z = zonal_sh_coefficients(weights, Eigen::Vector3d::UnitZ());
  for (int l = 0; l <= 8; ++l)
    for (int m = -l; m <= l; ++m) {
      const double expected = m == 0 ? std::sqrt(4 * pi / (2 * l + 1)) * weights[l] : 0.0;
      BOOST_TEST(std::abs(about_z[sh_index(l, m)] - expected) <= 1e-15);
    }
}

BOOST_AUTO_TEST_CASE(projection_recovers_a_band_limited_function) {
  // f = 3 + 2x - z^2: c_00 = int f Y_00 = (3 * 4 pi - 4 pi / 3) / sqrt(4 pi).
  const auto f = [](const Eigen::Vector3d& d) { return 3 + 2 * d.x() - d.z() * d.z(); };
  const Eigen::VectorXd c = project_sh(f, 4, product_sphere_quadrature(8));
  BOOST_TEST(c[0] == (12 * pi - 4 * pi / 3) / std::sqrt(4 * pi), tt::tolerance(1e-14));
  BOOST_TEST(c[sh_index(1, 1)] == 2 * std::sqrt(4 * pi / 3), tt::tolerance(1e-14));
  for (const Eigen::Vector3d& d : random_directions(10, 6))
    BOOST_TEST(evaluate_sh(c, d) == f(d), tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_SUITE_END()
