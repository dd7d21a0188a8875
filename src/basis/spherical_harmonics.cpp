#include "penumbra/basis/spherical_harmonics.h"

#include <cmath>
#include <stdexcept>

#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"

namespace penumbra::basis {
namespace {}  // namespace

int sh_degree(Eigen::Index coefficient_count) {
  const auto root = static_cast<Eigen::Index>(std::llround(std::sqrt(double(coefficient_count))));
  if (root < 1 || root * root != coefficient_count) return -1;
  return static_cast<int>(root - 1);
}

Eigen::VectorXd real_spherical_harmonics(int degree, const Eigen::Vector3d& direction) {
  if (degree < 0) throw std::invalid_argument("real_spherical_harmonics: negative degree");
  const double length = direction.norm();
  if (!(length > 0)) throw std::invalid_argument("real_spherical_harmonics: zero direction");
  const double x = direction.x() / length, y = direction.y() / length, z = direction.z() / length;
  Eigen::VectorXd values(sh_count(degree));
  // q_l^m = K_lm P_l^m(z) / sin^m(theta), built column by column in m:
  //   q_m^m     = q_{m-1}^{m-1} sqrt((2m + 1) / (2m)),     q_0^0 = 1 / sqrt(4 pi)
  //   q_{m+1}^m = sqrt(2m + 3) z q_m^m
  //   q_l^m     = a_lm (z q_{l-1}^m - b_lm q_{l-2}^m),
  //   a_lm = sqrt((4l^2 - 1) / (l^2 - m^2)), b_lm = sqrt(((l-1)^2 - m^2) / (4 (l-1)^2 - 1)).
  // These follow from the unnormalised (l - m) P_l^m = (2l - 1) z P_{l-1}^m
  // - (l + m - 1) P_{l-2}^m and P_m^m = (2m - 1)!! sin^m (docs/basis.md); the Appendix's
  // eq. (23) is not a complete recurrence.
  double diagonal = 1 / std::sqrt(4 * pi);
  double re = 1, im = 0;  // Re, Im of (x + i y)^m = sin^m(theta) e^{i m phi}
  for (int m = 0; m <= degree; ++m) {
    if (m > 0) {
      diagonal *= std::sqrt((2.0 * m + 1) / (2.0 * m));
      const double next_re = re * x - im * y;
      im = re * y + im * x;
      re = next_re;
    }
    const double scale_cos = m == 0 ? 1.0 : std::sqrt(2.0) * re;
    const double scale_sin = std::sqrt(2.0) * im;
    double before = 0, current = diagonal;
    for (int l = m; l <= degree; ++l) {
      if (l == m + 1) {
        before = current;
        current = std::sqrt(2.0 * m + 3) * z * before;
      } else if (l > m + 1) {
        const double a = std::sqrt((4.0 * l * l - 1) / (double(l) * l - double(m) * m));
        const double b =
            std::sqrt((double(l - 1) * (l - 1) - double(m) * m) / (4.0 * (l - 1) * (l - 1) - 1));
        const double next = a * (z * current - b * before);
        before = current;
        current = next;
      }
      values[sh_index(l, m)] = current * scale_cos;
      if (m > 0) values[sh_index(l, -m)] = current * scale_sin;
    }
  }
  return values;
}

double evaluate_sh(const Eigen::VectorXd& coefficients, const Eigen::Vector3d& direction) {
  const int degree = sh_degree(coefficients.size());
  if (degree < 0) throw std::invalid_argument("evaluate_sh: size is not (N + 1)^2");
  return coefficients.dot(real_spherical_harmonics(degree, direction));
}

Eigen::VectorXd zonal_sh_coefficients(const std::vector<double>& legendre_weights,
                                      const Eigen::Vector3d& axis) {
  if (legendre_weights.empty()) throw std::invalid_argument("zonal_sh_coefficients: no weights");
  const int degree = static_cast<int>(legendre_weights.size()) - 1;
  Eigen::VectorXd coefficients = real_spherical_harmonics(degree, axis);
  // Dobashi eqs. (7)-(10): P_l(a . r) = 4 pi / (2l + 1) sum_m Y_lm(a) Y_lm(r).
  for (int l = 0; l <= degree; ++l)
    for (int m = -l; m <= l; ++m)
      coefficients[sh_index(l, m)] *= 4 * pi / (2 * l + 1) * legendre_weights[l];
  return coefficients;
}

SphereQuadrature product_sphere_quadrature(int degree) {
  if (degree < 0) throw std::invalid_argument("product_sphere_quadrature: negative degree");
  const QuadratureRule in_z = gauss_legendre(degree / 2 + 1);
  const int azimuths = degree + 1;
  SphereQuadrature rule;
  for (std::size_t i = 0; i < in_z.nodes.size(); ++i) {
    const double z = in_z.nodes[i];
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    for (int k = 0; k < azimuths; ++k) {
      const double phi = 2 * pi * k / azimuths;
      rule.directions.emplace_back(s * std::cos(phi), s * std::sin(phi), z);
      rule.weights.push_back(in_z.weights[i] * 2 * pi / azimuths);
    }
  }
  return rule;
}

Eigen::VectorXd project_sh(const std::function<double(const Eigen::Vector3d&)>& function,
                           int degree, const SphereQuadrature& quadrature) {
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(sh_count(degree));
  for (std::size_t i = 0; i < quadrature.directions.size(); ++i) {
    const Eigen::Vector3d& d = quadrature.directions[i];
    coefficients += (quadrature.weights[i] * function(d)) * real_spherical_harmonics(degree, d);
  }
  return coefficients;
}

}  // namespace penumbra::basis
