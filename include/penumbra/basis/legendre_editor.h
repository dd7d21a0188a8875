#pragma once
// Interactive editing of a rotationally symmetric distribution by control points:
// Dobashi 1995 section 4.1, eqs. (19)-(21). The weights are trapezoid sums; moving
// one control point changes them by a rank-one correction. For accurate weights of a
// given distribution use legendre_weights() (legendre_series.h); these converge to
// them as the spacing shrinks (second order).

#include <vector>

#include "penumbra/basis/legendre_series.h"

namespace penumbra::basis {

// M + 1 control intensities at gamma_i = i pi / M, i = 0..M, and the Legendre weights
// of degree 0..N of the curve through them, by the trapezoid rule of eq. (19):
//   w_l = (2l + 1) / 2 * dgamma * sum_i t_i I_i f_l(gamma_i),  f_l(g) = P_l(cos g) sin g,
// t_0 = t_M = 1/2, t_i = 1 otherwise (eq. 21). The products (2l + 1) / 2 t_i f_l dgamma
// are stored as a table, as the paper suggests.
class LegendreWeightEditor {
 public:
  // builds the editor of control_intensities (candela, M + 1 >= 2 of them) for degrees
  // 0..degree. Preconditions: degree >= 0, at least two control points.
  LegendreWeightEditor(int degree, std::vector<double> control_intensities);

  // builds the editor of intervals + 1 samples of intensity at gamma_i = i pi / intervals.
  static LegendreWeightEditor sampled(const AxialProfile& intensity, int degree, int intervals);

  // moves control point k to intensity (candela) and updates the weights incrementally,
  // eq. (21) with its factor (2l + 1) / 2 restored:
  //   w_l += (2l + 1) / 2 * t_k (I_new - I_old) f_l(gamma_k) dgamma.
  // Precondition: 0 <= k <= M.
  void move_control_point(int k, double intensity);

  // returns the current weights w_0 .. w_N.
  const std::vector<double>& weights() const { return weights_; }
  // recomputes the weights from all control points with eq. (19).
  std::vector<double> recomputed_weights() const;

  const std::vector<double>& control_intensities() const { return controls_; }
  int degree() const { return degree_; }
  // returns M, the number of intervals.
  int intervals() const { return static_cast<int>(controls_.size()) - 1; }
  // returns the angle of control point k, k pi / M.
  double control_angle(int k) const;

 private:
  int degree_;
  std::vector<double> controls_;
  // table_[k * (N + 1) + l] = (2l + 1) / 2 t_k f_l(gamma_k) dgamma.
  std::vector<double> table_;
  std::vector<double> weights_;
};

}  // namespace penumbra::basis
