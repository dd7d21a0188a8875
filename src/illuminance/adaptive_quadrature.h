#pragma once
// Globally adaptive Gauss-Kronrod (7-15) quadrature, the numerical method kept beside the
// closed forms (Nishita 1985 section 4.2.1, Case C, integrates eq. (5) numerically; we refine
// where the error estimate is largest instead of choosing the step from min(r1, r2) / L).

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "penumbra/illuminance/linear_source.h"

namespace penumbra::illuminance::detail {

struct QuadraturePiece {
  double lo, hi, integral, error;
  bool operator<(const QuadraturePiece& other) const { return error < other.error; }
};

// returns the 15-point Kronrod estimate over [lo, hi] and |Kronrod - Gauss(7)|.
template <class Integrand>
QuadraturePiece gauss_kronrod_15(Integrand& f, double lo, double hi) {
  // Abscissae and weights of QUADPACK's qk15 (Piessens et al. 1983).
  static constexpr double node[8] = {
      0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
      0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
      0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
      0.207784955007898467600689403773245, 0.0};
  static constexpr double kronrod_weight[8] = {
      0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
      0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
      0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
      0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
  static constexpr double gauss_weight[4] = {
      0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
      0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
  const double centre = 0.5 * (lo + hi);
  const double half = 0.5 * (hi - lo);
  const double f_centre = f(centre);
  double kronrod = kronrod_weight[7] * f_centre;
  double gauss = gauss_weight[3] * f_centre;
  for (int i = 0; i < 7; ++i) {
    const double sum = f(centre - half * node[i]) + f(centre + half * node[i]);
    kronrod += kronrod_weight[i] * sum;
    if (i % 2 == 1) gauss += gauss_weight[i / 2] * sum;
  }
  return {lo, hi, kronrod * half, std::abs((kronrod - gauss) * half)};
}

// returns the sorted breakpoints lo, hi and centre +- width 4^k (k = 0, 1, ...) inside (lo, hi):
// an integrand peaked at `centre` with `width` (eq. (5) near its foot: height ~ 1/h, width
// ~ h) is then smooth on every piece at its own scale, and no first pass can step over the
// peak (the paper's Case C makes its step grow with the distance for the same reason).
inline std::vector<double> graded_breakpoints(double lo, double hi, double centre, double width) {
  std::vector<double> breaks{lo, hi};
  if (centre > lo && centre < hi) breaks.push_back(centre);
  if (width > 0)
    for (double offset = width; offset < hi - lo; offset *= 4)
      for (double at : {centre - offset, centre + offset})
        if (at > lo && at < hi) breaks.push_back(at);
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

// integrates f over the consecutive intervals between sorted `breakpoints`, bisecting the
// piece with the largest error estimate until the summed estimate meets the tolerance.
template <class Integrand>
double integrate_adaptive(Integrand f, const std::vector<double>& breakpoints,
                          const QuadratureOptions& options) {
  std::priority_queue<QuadraturePiece> pieces;
  for (std::size_t i = 0; i + 1 < breakpoints.size(); ++i)
    if (breakpoints[i + 1] > breakpoints[i])
      pieces.push(gauss_kronrod_15(f, breakpoints[i], breakpoints[i + 1]));
  if (pieces.empty()) return 0;
  auto totals = [&pieces] {
    double integral = 0, error = 0;
    auto copy = pieces;
    for (; !copy.empty(); copy.pop()) {
      integral += copy.top().integral;
      error += copy.top().error;
    }
    return std::pair{integral, error};
  };
  double integral = 0, error = 0;
  std::tie(integral, error) = totals();
  int count = static_cast<int>(pieces.size());
  while (error > std::max(options.absolute_tolerance,
                          options.relative_tolerance * std::abs(integral)) &&
         count < options.max_subintervals) {
    const QuadraturePiece worst = pieces.top();
    const double middle = 0.5 * (worst.lo + worst.hi);
    if (!(middle > worst.lo && middle < worst.hi)) break;  // the piece cannot be split further
    pieces.pop();
    const QuadraturePiece left = gauss_kronrod_15(f, worst.lo, middle);
    const QuadraturePiece right = gauss_kronrod_15(f, middle, worst.hi);
    pieces.push(left);
    pieces.push(right);
    ++count;
    integral += left.integral + right.integral - worst.integral;
    error += left.error + right.error - worst.error;
    // Re-sum now and then so that the running totals do not drift.
    if (count % 64 == 0) std::tie(integral, error) = totals();
  }
  return totals().first;
}

}  // namespace penumbra::illuminance::detail
