#pragma once
// Closed forms the basis tests compare against (docs/basis.md derives them).

#include <cmath>

namespace penumbra::test {

inline constexpr double kPi = 3.14159265358979323846;

// returns the integral of x^n P_l(x) over [0, 1] for real n > -1, from
// Gradshteyn-Ryzhik 7.126.2 with mu = n:
//   sqrt(pi) 2^(-n-1) Gamma(n + 1) / (Gamma(1 + n/2 - l/2) Gamma(n/2 + l/2 + 3/2)).
// 1 / Gamma vanishes at the poles 1 + n/2 - l/2 = 0, -1, ... (orthogonality: x^n is a
// combination of P_n, P_n-2, ... when n is an integer and l - n even).
inline double moment_of_legendre(double n, int l) {
  const double first = 1 + n / 2 - l / 2.0;
  if (first <= 0 && first == std::floor(first)) return 0;
  return std::sqrt(kPi) * std::pow(2.0, -n - 1) * std::tgamma(n + 1) /
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

}  // namespace penumbra::test
