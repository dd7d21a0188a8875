#pragma once
// Illuminance from point and directional sources: Nishita 1985 section 3.3, eqs. (2)-(4).
// Doubles only: this header decides no geometric question (shadows are the shadow layer's
// business); it turns "the lamp is seen from P" into lux. See docs/illuminance.md.

#include <array>
#include <type_traits>
#include <utility>
#include "penumbra/base/vec3d.h"

namespace penumbra {

// A double-precision triple; the same alias as in geometry/kernel.h, restated here so
// that magnitude code does not pull in the exact kernel's headers.

namespace illuminance {

// computes the illuminance (lux) at `point` on a surface with unit outward `normal` from an
// isotropic-in-this-direction point source at `lamp` sending `candela` toward `point`:
// E = I cos(alpha) / r^2 = I F(S_f, lamp) / r^3 (Nishita 1985, eqs. (2) and (4)).
// Tie-break: returns 0 unless the lamp is strictly on the outer side of the plane through
// `point` with normal `normal` (normal . (lamp - point) > 0); grazing light gives 0, and so
// does lamp == point.
//   @param[in] point   receiving point P (m)
//   @param[in] normal  unit outward normal N at P
//   @param[in] lamp    source position Q (m)
//   @param[in] candela luminous intensity of the source toward P (cd)
double point_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& lamp,
                         double candela);

// computes the same illuminance for a source with a luminous intensity distribution:
// `intensity_toward(direction)` receives the unit vector from the lamp toward `point` in
// world coordinates and returns the intensity in candela in that direction (the photometry
// layer maps it to its (gamma, c) angles). It is not called when the result is 0 by the
// tie-break above.
template <class IntensityToward,
          std::enable_if_t<std::is_invocable_r_v<double, IntensityToward&, const Vec3d&>, int> = 0>
double point_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& lamp,
                         IntensityToward&& intensity_toward);

// computes the illuminance (lux) on a surface with unit outward `normal` from a directional
// source (the sun) whose light travels along `travel_direction` (need not be unit length) and
// gives `normal_illuminance` (lux) on a plane perpendicular to it: E = E_n cos(alpha).
// Returns 0 unless the light arrives strictly from the outer side (normal . travel < 0).
double directional_illuminance(const Vec3d& normal, const Vec3d& travel_direction,
                               double normal_illuminance);

// === Implementation of the template

namespace detail {
// returns (cos(alpha) / r^2, unit direction lamp -> point); cos(alpha) / r^2 is 0 when the
// lamp is not strictly on the outer side.
std::pair<double, Vec3d> point_geometry(const Vec3d& point, const Vec3d& normal, const Vec3d& lamp);
}  // namespace detail

template <class IntensityToward,
          std::enable_if_t<std::is_invocable_r_v<double, IntensityToward&, const Vec3d&>, int>>
double point_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& lamp,
                         IntensityToward&& intensity_toward) {
  const auto [cos_over_r2, direction] = detail::point_geometry(point, normal, lamp);
  if (cos_over_r2 == 0) return 0;
  return intensity_toward(direction) * cos_over_r2;
}

}  // namespace illuminance
}  // namespace penumbra
