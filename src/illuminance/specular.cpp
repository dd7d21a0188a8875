#include "penumbra/illuminance/specular.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "adaptive_quadrature.h"
#include "line_frame.h"
#include "penumbra/base/numbers.h"
#include "penumbra/base/vec3d.h"

namespace penumbra::illuminance {

using namespace vector_ops;

namespace {

using namespace detail;

// returns cos^n(psi) for the light arriving from unit direction `to_light`, or 0 when the
// light or the viewer is not strictly on the outer side or cos(psi) <= 0 (Phong 1975).
double phong_lobe(const Vec3d& normal, const Vec3d& to_viewer, const Vec3d& to_light,
                  double shininess) {
  const double cos_alpha = dot(normal, to_light);
  if (!(cos_alpha > 0) || !(dot(normal, to_viewer) > 0)) return 0;
  const Vec3d mirror = 2 * cos_alpha * normal - to_light;
  const double cos_psi = dot(mirror, to_viewer);
  if (!(cos_psi > 0)) return 0;
  return std::pow(cos_psi, shininess);
}

}  // namespace

double point_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                      const Vec3d& lamp, double candela, const PhongSpecular& material) {
  const Vec3d to_lamp = lamp - point;
  const double r_squared = dot(to_lamp, to_lamp);
  if (!(r_squared > 0)) return 0;
  const Vec3d to_light = (1 / std::sqrt(r_squared)) * to_lamp;
  return material.specular / pi * candela / r_squared *
         phong_lobe(normal, to_viewer, to_light, material.shininess);
}

double linear_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                       const Vec3d& a, const Vec3d& b, double candela_per_metre,
                       const PhongSpecular& material, const QuadratureOptions& options) {
  return linear_specular(point, normal, to_viewer, a, b, candela_per_metre, material, {{0.0, 1.0}},
                         options);
}

double linear_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                       const Vec3d& a, const Vec3d& b, double candela_per_metre,
                       const PhongSpecular& material, const std::vector<SourceInterval>& visible,
                       const QuadratureOptions& options) {
  for (const auto& [first, second] : visible)
    if (!(0 <= first && first <= second && second <= 1))
      throw std::invalid_argument("linear source interval must satisfy 0 <= first <= second <= 1");
  const LineFrame frame = line_frame(point, normal, a, b);
  const auto outer = outer_side_interval(point, normal, a, b);
  if (!(frame.length > 0) || !outer || material.specular == 0) return 0;

  // Nishita 1985 section 4.2.1 (end): the source as a series of point sources, element dl of
  // intensity I sin(theta) dl at distance r, each giving Phong's term.
  // The element with Q - P = v.
  auto element = [&](const Vec3d& v) {
    const double r_squared = dot(v, v);
    if (!(r_squared > 0)) return 0.0;
    const Vec3d to_light = (1 / std::sqrt(r_squared)) * v;
    const double sin_theta = length(cross(frame.axis, to_light));
    return sin_theta / r_squared * phong_lobe(normal, to_viewer, to_light, material.shininess);
  };

  // Break the integral where the integrand can be narrow: around the foot of the
  // perpendicular (width ~ h), at the element nearest to the mirror ray of the view
  // direction (the highlight, width ~ r / sqrt(n)) and in eight even pieces, so that the
  // first Gauss-Kronrod pass cannot step over a peak.
  std::optional<double> highlight;
  const Vec3d mirror_view = 2 * dot(normal, to_viewer) * normal - to_viewer;
  const double cos_between = dot(frame.axis, mirror_view);
  const double sin_squared = 1 - cos_between * cos_between;
  if (sin_squared > 1e-12) {
    // Closest point of the line P + w + t d to the ray P + lambda R (d, R unit, d . w = 0).
    highlight = cos_between * dot(mirror_view, frame.perpendicular) / sin_squared;
  }

  double sum = 0;
  for (const auto& [first, second] : visible) {
    const double u0 = std::max(first, outer->first);
    const double u1 = std::min(second, outer->second);
    if (!(u1 > u0)) continue;
    const QuadratureSpan span = quadrature_span(frame, u0, u1);
    const double lo = span.lo, hi = span.hi;
    std::vector<double> breaks = graded_breakpoints(lo, hi, span.foot, frame.distance);
    constexpr int initial_pieces = 8;
    for (int i = 1; i < initial_pieces; ++i) breaks.push_back(lo + (hi - lo) * i / initial_pieces);
    // The highlight's t, measured in sigma (sigma = t + foot).
    if (highlight && *highlight + span.foot > lo && *highlight + span.foot < hi)
      breaks.push_back(*highlight + span.foot);
    std::sort(breaks.begin(), breaks.end());
    sum += integrate_adaptive(
        [&](double sigma) { return element(span.origin + sigma * frame.axis); }, breaks, options);
  }
  return material.specular / pi * candela_per_metre * sum;
}

}  // namespace penumbra::illuminance
