#include "penumbra/base/gauss_legendre.h"

#include <cmath>
#include <stdexcept>
#include "penumbra/base/numbers.h"

namespace penumbra {
namespace {

struct LegendreValue {
  double value;       // P_n(x)
  double derivative;  // P'_n(x)
};

// Bonnet's recurrence (l + 1) P_{l+1} = (2l + 1) x P_l - l P_{l-1}, then
// P'_n = n (x P_n - P_{n-1}) / (x^2 - 1), valid away from x = +-1 (the nodes are).
LegendreValue legendre_with_derivative(int n, double x) {
  double previous = 1, current = x;
  if (n == 0) return {1, 0};
  for (int l = 1; l < n; ++l) {
    const double next = ((2 * l + 1) * x * current - l * previous) / (l + 1);
    previous = current;
    current = next;
  }
  return {current, n * (x * current - previous) / (x * x - 1)};
}

}  // namespace

QuadratureRule gauss_legendre(int points) {
  if (points < 1) throw std::invalid_argument("gauss_legendre: points must be >= 1");
  QuadratureRule rule;
  rule.nodes.resize(points);
  rule.weights.resize(points);
  // The rule is symmetric: find the nonnegative half, mirror the rest.
  for (int i = 1; i <= (points + 1) / 2; ++i) {
    double x = std::cos(pi * (i - 0.25) / (points + 0.5));
    LegendreValue p{};
    for (int iteration = 0; iteration < 100; ++iteration) {
      p = legendre_with_derivative(points, x);
      const double step = p.value / p.derivative;
      x -= step;
      if (std::abs(step) <= 1e-16 * std::abs(x) + 1e-300) break;
    }
    p = legendre_with_derivative(points, x);
    const double weight = 2 / ((1 - x * x) * p.derivative * p.derivative);
    // i counts from the largest node down.
    rule.nodes[points - i] = x;
    rule.weights[points - i] = weight;
    rule.nodes[i - 1] = -x;
    rule.weights[i - 1] = weight;
  }
  if (points % 2 == 1) rule.nodes[points / 2] = 0;
  return rule;
}

QuadratureRule mapped(const QuadratureRule& rule, double a, double b) {
  QuadratureRule out;
  const double half = 0.5 * (b - a), middle = 0.5 * (a + b);
  out.nodes.reserve(rule.nodes.size());
  out.weights.reserve(rule.weights.size());
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    out.nodes.push_back(middle + half * rule.nodes[i]);
    out.weights.push_back(half * rule.weights[i]);
  }
  return out;
}

}  // namespace penumbra
