#pragma once
// Rotationally symmetric luminous intensity distributions as Legendre series:
// Dobashi 1995 section 3.1, eqs. (2)-(3). docs/basis.md has the derivations.

#include <functional>
#include <vector>

namespace penumbra::basis {

// An intensity that depends only on gamma, the angle from the lamp's axis (radians,
// 0..pi), in candela.
using AxialProfile = std::function<double(double gamma)>;

// returns P_0(x) .. P_degree(x) by Bonnet's recurrence
// (l + 1) P_{l+1}(x) = (2l + 1) x P_l(x) - l P_{l-1}(x). Precondition: degree >= 0.
std::vector<double> legendre_polynomials(int degree, double x);

// A truncated Legendre series I(gamma) = sum_{l=0}^N w_l P_l(cos gamma), eq. (2).
class LegendreSeries {
 public:
  LegendreSeries() = default;
  // builds the series of weights w_0 .. w_N (candela). Precondition: not empty.
  explicit LegendreSeries(std::vector<double> weights);

  // returns N, the highest degree.
  int degree() const { return static_cast<int>(weights_.size()) - 1; }
  const std::vector<double>& weights() const { return weights_; }

  // evaluates eq. (2) toward gamma (radians from the axis).
  double operator()(double gamma) const;
  // evaluates eq. (2) at cos gamma = x, summing along Bonnet's recurrence.
  double at_cosine(double x) const;

  // returns the series with w_l replaced by sigma(N, l) w_l, eq. (12).
  LegendreSeries sigma_smoothed() const;

  // returns the flux in lumen, 4 pi w_0: over the sphere every P_l with l > 0 integrates
  // to zero (orthogonality to P_0).
  double flux() const;

 private:
  std::vector<double> weights_;
};

// computes the weights w_0 .. w_degree of eq. (3),
//   w_l = (2l + 1) / 2 * int_0^pi I(gamma) P_l(cos gamma) sin gamma dgamma,
// by Gauss-Legendre quadrature in gamma on every interval between consecutive
// breakpoints (radians; 0 and pi are added, values outside are ignored). Give the kinks
// and jumps of the profile (table angles, a spot's spread) as breakpoints: inside each
// interval the integrand is then smooth and the rule converges exponentially.
// points_per_interval = 0 chooses 2 degree + 24, which integrates the weights of the
// closed forms of the tests to round-off. Precondition: degree >= 0.
std::vector<double> legendre_weights(const AxialProfile& intensity, int degree,
                                     std::vector<double> breakpoints = {},
                                     int points_per_interval = 0);

// returns the sorted, deduplicated breakpoints within [0, pi], with 0 and pi included.
std::vector<double> normalised_breakpoints(std::vector<double> breakpoints);

}  // namespace penumbra::basis
