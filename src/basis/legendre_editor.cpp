#include "penumbra/basis/legendre_editor.h"

#include <cmath>
#include <stdexcept>
#include "penumbra/base/numbers.h"

namespace penumbra::basis {
namespace {}  // namespace

LegendreWeightEditor::LegendreWeightEditor(int degree, std::vector<double> control_intensities)
    : degree_(degree), controls_(std::move(control_intensities)) {
  if (degree < 0) throw std::invalid_argument("LegendreWeightEditor: negative degree");
  if (controls_.size() < 2)
    throw std::invalid_argument("LegendreWeightEditor: needs at least two control points");
  const int m = intervals();
  const double spacing = pi / m;
  table_.resize(controls_.size() * (degree + 1));
  for (int k = 0; k <= m; ++k) {
    const double gamma = control_angle(k);
    // Dobashi eq. (21): t_k halves the end points of the trapezoid rule.
    const double t = (k == 0 || k == m) ? 0.5 : 1.0;
    // Eq. (20): f_l = P_l(cos g) sin g. At the poles sin g = 0 exactly, so the on-axis
    // and back intensities carry no weight: a point of the sphere has no area.
    const double sine = (k == 0 || k == m) ? 0.0 : std::sin(gamma);
    const std::vector<double> p = legendre_polynomials(degree, std::cos(gamma));
    for (int l = 0; l <= degree; ++l)
      table_[k * (degree + 1) + l] = 0.5 * (2 * l + 1) * t * p[l] * sine * spacing;
  }
  weights_ = recomputed_weights();
}

LegendreWeightEditor LegendreWeightEditor::sampled(const AxialProfile& intensity, int degree,
                                                   int intervals) {
  if (intervals < 1) throw std::invalid_argument("LegendreWeightEditor: intervals must be >= 1");
  std::vector<double> controls(intervals + 1);
  for (int k = 0; k <= intervals; ++k) controls[k] = intensity(pi * k / intervals);
  return LegendreWeightEditor(degree, std::move(controls));
}

double LegendreWeightEditor::control_angle(int k) const {
  return pi * k / intervals();
}

std::vector<double> LegendreWeightEditor::recomputed_weights() const {
  // Dobashi eq. (19), a trapezoid rule (the scan calls it Simpson's).
  std::vector<double> weights(degree_ + 1, 0.0);
  for (std::size_t k = 0; k < controls_.size(); ++k)
    for (int l = 0; l <= degree_; ++l) weights[l] += controls_[k] * table_[k * (degree_ + 1) + l];
  return weights;
}

void LegendreWeightEditor::move_control_point(int k, double intensity) {
  if (k < 0 || k > intervals())
    throw std::invalid_argument("LegendreWeightEditor: no such control point");
  // Dobashi eq. (21), a rank-one update along column k of the table.
  const double change = intensity - controls_[k];
  for (int l = 0; l <= degree_; ++l) weights_[l] += change * table_[k * (degree_ + 1) + l];
  controls_[k] = intensity;
}

}  // namespace penumbra::basis
