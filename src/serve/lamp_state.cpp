// The designer's state of one lamp (include/penumbra/serve/lamp_state.h).

#include "penumbra/serve/lamp_state.h"

#include <cmath>
#include <stdexcept>

#include "penumbra/base/numbers.h"
#include "penumbra/basis/legendre_series.h"
#include "penumbra/basis/relight.h"
#include "penumbra/basis/sigma_factors.h"

namespace penumbra::serve {
using namespace penumbra::vector_ops;
namespace {

nlohmann::json vector_json(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<double> LampState::lighting_weights() const {
  if (!editor) throw std::logic_error("lighting_weights: " + name + " is not a point lamp");
  std::vector<double> weights = editor->weights();
  // Dobashi 1995 eq. (12): w_l -> sigma(N, l) w_l against the Gibbs ripples.
  if (sigma) {
    const std::vector<double> factors = basis::sigma_factors(editor->degree());
    for (std::size_t l = 0; l < weights.size(); ++l) weights[l] *= factors[l];
  }
  return weights;
}

Eigen::VectorXd LampState::coefficients() const {
  if (!editor) return Eigen::VectorXd::Constant(1, 1.0);
  // Eq. (10): c_lm = A_lm(axis) w_l, the series turned to the lamp's axis.
  return basis::world_coefficients(lighting_weights(), axis);
}

void LampState::aim_along(const Vec3d& direction) {
  if (kind != basis::LightKind::point)
    throw std::invalid_argument(name + " is not a point lamp: it cannot be aimed");
  const double norm = length(direction);
  if (!std::isfinite(norm) || norm < 1e-9)
    throw std::invalid_argument("the aim direction of " + name + " has no length");
  axis = (1 / norm) * direction;
  c0 = basis::reaimed_c0(axis, c0);
}

void LampState::aim_at(const Vec3d& point) {
  aim_along(point - position);
}

nlohmann::json describe(const LampState& lamp) {
  nlohmann::json out = {{"name", lamp.name},
                        {"kind", basis::kind_name(lamp.kind)},
                        {"colour", lamp.colour},
                        {"scale", lamp.scale},
                        {"editable", lamp.editor.has_value()}};
  if (lamp.kind != basis::LightKind::point || !lamp.editor) return out;
  const basis::LegendreWeightEditor& editor = *lamp.editor;
  out["degree"] = lamp.degree;
  out["position"] = vector_json(lamp.position);
  out["axis"] = vector_json(lamp.axis);
  out["c0"] = vector_json(lamp.c0);
  out["sigma"] = lamp.sigma;
  nlohmann::json angles = nlohmann::json::array();
  for (int k = 0; k <= editor.intervals(); ++k)
    angles.push_back(editor.control_angle(k) * 180 / pi);
  out["controls"] = {{"angles_deg", angles}, {"candela", editor.control_intensities()}};
  out["weights"] = editor.weights();
  out["sigma_factors"] = basis::sigma_factors(editor.degree());
  // The curve the lamp is lit with (eq. 2, or eq. 12 with sigma), for the polar editor.
  const basis::LegendreSeries series(lamp.lighting_weights());
  nlohmann::json samples = nlohmann::json::array();
  for (int degrees = 0; degrees <= 180; degrees += 2) samples.push_back(series(degrees * pi / 180));
  out["approximation"] = {{"step_deg", 2}, {"candela", samples}};
  return out;
}

}  // namespace penumbra::serve
