#include "penumbra/basis/legendre_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/sigma_factors.h"

namespace penumbra::basis {
namespace {}  // namespace

std::vector<double> legendre_polynomials(int degree, double x) {
  if (degree < 0) throw std::invalid_argument("legendre_polynomials: negative degree");
  std::vector<double> values(degree + 1);
  values[0] = 1;
  if (degree >= 1) values[1] = x;
  for (int l = 1; l < degree; ++l)
    values[l + 1] = ((2 * l + 1) * x * values[l] - l * values[l - 1]) / (l + 1);
  return values;
}

LegendreSeries::LegendreSeries(std::vector<double> weights) : weights_(std::move(weights)) {
  if (weights_.empty()) throw std::invalid_argument("LegendreSeries: no weights");
}

double LegendreSeries::operator()(double gamma) const {
  return at_cosine(std::cos(gamma));
}

double LegendreSeries::at_cosine(double x) const {
  double previous = 1, current = x;
  double sum = weights_[0];
  if (weights_.size() > 1) sum += weights_[1] * x;
  for (int l = 1; l < degree(); ++l) {
    const double next = ((2 * l + 1) * x * current - l * previous) / (l + 1);
    previous = current;
    current = next;
    sum += weights_[l + 1] * current;
  }
  return sum;
}

LegendreSeries LegendreSeries::sigma_smoothed() const {
  std::vector<double> smoothed = weights_;
  // Dobashi eq. (12): the sigma factors multiply the weights of eq. (3).
  for (int l = 0; l <= degree(); ++l) smoothed[l] *= sigma_factor(degree(), l);
  return LegendreSeries(std::move(smoothed));
}

double LegendreSeries::flux() const {
  return 4 * pi * weights_[0];
}

std::vector<double> normalised_breakpoints(std::vector<double> breakpoints) {
  breakpoints.erase(std::remove_if(breakpoints.begin(), breakpoints.end(),
                                   [](double b) { return !(b > 0 && b < pi); }),
                    breakpoints.end());
  breakpoints.push_back(0);
  breakpoints.push_back(pi);
  std::sort(breakpoints.begin(), breakpoints.end());
  breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());
  return breakpoints;
}

std::vector<double> legendre_weights(const AxialProfile& intensity, int degree,
                                     std::vector<double> breakpoints, int points_per_interval) {
  if (degree < 0) throw std::invalid_argument("legendre_weights: negative degree");
  if (points_per_interval <= 0) points_per_interval = 2 * degree + 24;
  const QuadratureRule reference = gauss_legendre(points_per_interval);
  const std::vector<double> edges = normalised_breakpoints(std::move(breakpoints));
  std::vector<double> integrals(degree + 1, 0.0);
  // Dobashi eq. (3), integrated in gamma (not in cos gamma): a table linear in gamma
  // is smooth in gamma inside each interval, but has an infinite derivative in
  // cos gamma at the poles.
  for (std::size_t piece = 0; piece + 1 < edges.size(); ++piece) {
    const QuadratureRule rule = mapped(reference, edges[piece], edges[piece + 1]);
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const double gamma = rule.nodes[i];
      const double weighted = rule.weights[i] * intensity(gamma) * std::sin(gamma);
      const std::vector<double> p = legendre_polynomials(degree, std::cos(gamma));
      for (int l = 0; l <= degree; ++l) integrals[l] += weighted * p[l];
    }
  }
  for (int l = 0; l <= degree; ++l) integrals[l] *= 0.5 * (2 * l + 1);
  return integrals;
}

}  // namespace penumbra::basis
