#pragma once
// What the designer edits of one light in the browser tool (Dobashi 1995 section 4):
// a point lamp's intensity curve by control points (section 4.1, eqs. 19-21), its aim
// (section 4.2), sigma factors on or off (section 3.3.2, eq. 12), colour and dimming.
// A linear source or the sun keeps its own distribution: only colour and dimming apply.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "penumbra/base/colour.h"
#include "penumbra/base/vec3d.h"
#include "penumbra/basis/direct_lighting.h"
#include "penumbra/basis/legendre_editor.h"

namespace penumbra::serve {

// The number of control intervals over 0..180 degrees by default: a point every 10
// degrees.
inline constexpr int default_control_intervals = 18;

struct LampState {
  std::string name;
  basis::LightKind kind = basis::LightKind::point;
  int degree = -1;       // SH degree of the basis (point lamps), else -1
  Vec3d position{};      // point lamps
  Vec3d axis{0, 0, -1};  // unit
  Vec3d c0{1, 0, 0};     // unit, orthogonal to axis
  Colour colour{1, 1, 1};
  double scale = 1;   // dimming, >= 0
  bool sigma = true;  // apply sigma factors to the Legendre weights (eq. 12)
  std::optional<basis::LegendreWeightEditor> editor;  // point lamps: the curve being edited

  // returns the Legendre weights used for lighting: the editor's, times sigma(N, l) when
  // sigma is on. Precondition: a point lamp.
  std::vector<double> lighting_weights() const;

  // returns the world SH coefficients of the lamp (eq. 10 about axis), or [1] for a
  // linear source or the sun.
  Eigen::VectorXd coefficients() const;

  // aims the lamp at point (section 4.2): the axis from the lamp toward point. Throws
  // std::invalid_argument for a lamp that is not a point lamp, or a point at the lamp.
  void aim_at(const Vec3d& point);
  // aims along direction (any length > 0). Throws as aim_at.
  void aim_along(const Vec3d& direction);
};

// returns the lamp's state as the API shows it: name, kind, position, axis, colour,
// scale, sigma and, for a point lamp, its control points (degrees, candela), weights
// w_0..w_N as edited (eq. 21, without sigma factors), the sigma factors and the series
// actually lit with, sampled every 2 degrees for drawing.
nlohmann::json describe(const LampState& lamp);

}  // namespace penumbra::serve
