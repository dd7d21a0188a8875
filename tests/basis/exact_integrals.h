#pragma once
// Closed forms the basis tests compare against (docs/basis.md derives them).

#include <cmath>
#include "penumbra/base/numbers.h"

namespace penumbra::test {

// returns the integral of x^n P_l(x) over [0, 1] for real n > -1, from
// Gradshteyn-Ryzhik 7.126.2 with mu = n:
//   sqrt(pi) 2^(-n-1) Gamma(n + 1) / (Gamma(1 + n/2 - l/2) Gamma(n/2 + l/2 + 3/2)).
// 1 / Gamma vanishes at the poles 1 + n/2 - l/2 = 0, -1, ... (orthogonality: x^n is a
// combination of P_n, P_n-2, ... when n is an integer and l - n even).
inline double moment_of_legendre(double n, int l) {
  const double first = 1 + n / 2 - l / 2.0;
  if (first <= 0 && first == std::floor(first)) return 0;
  return std::sqrt(pi) * std::pow(2.0, -n - 1) * std::tgamma(n + 1) /
         (std::tgamma(first) * std::tgamma(n / 2 + l / 2.0 + 1.5));
}

// returns the binomial coefficient, exactly for the small arguments of the tests.
inline long double binomial(int n, int k) {
  long double value = 1;
  for (int i = 1; i <= k; ++i) value = value * (n - k + i) / i;
  return value;
}

// returns the integral of x^n P_l(x) over [a, 1] for integer n >= 0, term by term from
// P_l(x) = 2^-l sum_j (-1)^j C(l, j) C(2l - 2j, l) x^(l - 2j) (Rodrigues' formula
// expanded). Long double keeps the alternating sum accurate to ~1e-15 for l <= 10.
inline double moment_of_legendre_from(double a, int n, int l) {
  long double sum = 0;
  for (int j = 0; 2 * j <= l; ++j) {
    const int power = n + l - 2 * j + 1;
    const long double term = binomial(l, j) * binomial(2 * l - 2 * j, l) *
                             (1 - std::pow(static_cast<long double>(a), power)) / power;
    sum += (j % 2 == 0) ? term : -term;
  }
  return static_cast<double>(sum / std::pow(2.0L, l));
}

// returns the integral of (a + b g) P_l(cos g) sin g over [from, to], exactly, from the
// Fourier form P_l(cos g) = 4^-l sum_{k=0}^{l} C(2k, k) C(2l - 2k, l - k) cos((l - 2k) g)
// (Whittaker-Watson 15.1), cos(n g) sin g = (sin((n + 1) g) - sin((n - 1) g)) / 2 and
// int (a + b g) sin(m g) dg = -(a + b g) cos(m g) / m + b sin(m g) / m^2.
inline double linear_times_legendre(int l, double from, double to, double a, double b) {
  const auto sine_moment = [&](int m) {
    if (m == 0) return 0.0;
    const auto antiderivative = [&](double g) {
      return -(a + b * g) * std::cos(m * g) / m + b * std::sin(m * g) / (double(m) * m);
    };
    return antiderivative(to) - antiderivative(from);
  };
  long double sum = 0;
  for (int k = 0; k <= l; ++k) {
    const int n = l - 2 * k;
    sum += binomial(2 * k, k) * binomial(2 * l - 2 * k, l - k) *
           (sine_moment(n + 1) - sine_moment(n - 1)) / 2;
  }
  return static_cast<double>(sum / std::pow(4.0L, l));
}

// returns w_l of eq. (3) for the curve linear in gamma between (nodes[i], candela[i]),
// exactly, piece by piece with linear_times_legendre.
template <class Vector>
double table_weight(int l, const Vector& nodes, const Vector& candela) {
  double integral = 0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double slope = (candela[i + 1] - candela[i]) / (nodes[i + 1] - nodes[i]);
    integral +=
        linear_times_legendre(l, nodes[i], nodes[i + 1], candela[i] - slope * nodes[i], slope);
  }
  return (2 * l + 1) / 2.0 * integral;
}

}  // namespace penumbra::test
