#include "penumbra/photometry/figures.h"

#include <algorithm>
#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/photometry/orientation.h"

namespace penumbra::photometry {
namespace {

constexpr int kScanSteps = 3600;  // 0.05 degree steps over 0..180

bool is_axial(const Distribution& distribution) {
  return distribution.symmetry() == Symmetry::axial ||
         distribution.symmetry() == Symmetry::isotropic;
}

// returns the full angle (degrees) of the arc of the great circle through peak along
// tangent over which I >= level, walking both ways from peak.
double arc_angle(const Distribution& distribution, const Vec3d& peak, const Vec3d& tangent,
                 double level) {
  const Vec3d axis{0, 0, 1}, c0{1, 0, 0};  // the photometric frame as coordinates
  auto intensity_at = [&](double theta, double sign) {
    const double a = std::cos(theta), b = sign * std::sin(theta);
    return intensity_toward(
        distribution, axis, c0,
        {a * peak[0] + b * tangent[0], a * peak[1] + b * tangent[1], a * peak[2] + b * tangent[2]});
  };
  double total = 0;
  for (double sign : {1.0, -1.0}) {
    const double step = pi / kScanSteps;
    double inside = 0, outside = pi;
    bool found = false;
    for (int k = 1; k <= kScanSteps; ++k)
      if (intensity_at(k * step, sign) < level) {
        inside = (k - 1) * step;
        outside = k * step;
        found = true;
        break;
      }
    if (!found) return 360;  // the whole great circle is lit
    for (int i = 0; i < 60; ++i) {
      const double middle = 0.5 * (inside + outside);
      (intensity_at(middle, sign) >= level ? inside : outside) = middle;
    }
    total += inside;
  }
  return degrees(total);
}

}  // namespace

std::optional<double> outermost_gamma(const Distribution& distribution, double c, double level) {
  const double step = pi / kScanSteps;
  for (int k = kScanSteps; k >= 0; --k) {
    double inside = k * step;
    if (distribution.intensity(inside, c) < level) continue;
    if (k == kScanSteps) return pi;
    // I(inside) >= level > I(outside): bisect the crossing.
    double outside = (k + 1) * step;
    for (int i = 0; i < 60; ++i) {
      const double middle = 0.5 * (inside + outside);
      (distribution.intensity(middle, c) >= level ? inside : outside) = middle;
    }
    return inside;
  }
  return std::nullopt;
}

PartialSphere partial_sphere(const Distribution& distribution, const FigureOptions& options) {
  PartialSphere sphere;
  sphere.threshold = options.threshold;
  sphere.full_scale_lux = options.full_scale_lux;
  const double max_candela = distribution.max_intensity();
  const double level = options.threshold * max_candela;
  const int planes = is_axial(distribution) ? 1 : 360;
  double spread = 0;
  for (int j = 0; j < planes; ++j)
    if (const auto gamma = outermost_gamma(distribution, radians(j), level))
      spread = std::max(spread, *gamma);
  sphere.spread_deg = degrees(spread);
  // r such that I / r^2 = threshold * E_full.
  auto radius = [&](double candela) {
    return std::sqrt(candela / (options.threshold * options.full_scale_lux));
  };
  sphere.radius_m = radius(max_candela);
  sphere.two_spheres = spread > pi / 2;
  if (!sphere.two_spheres) {
    sphere.lower_radius_m = sphere.radius_m;
    return sphere;
  }
  // Fig. 2b: the hemisphere holding the maximum takes r_a; the other its own maximum,
  // sampled every 0.25 degree in gamma and 1 degree in C.
  const bool max_lower = distribution.max_direction().gamma <= pi / 2;
  double other = 0;
  for (int j = 0; j < planes; ++j)
    for (int k = 0; k <= 360; ++k) {
      const double gamma = max_lower ? pi / 2 + k * (pi / 720) : k * (pi / 720);
      if (max_lower && gamma == pi / 2) continue;
      other = std::max(other, distribution.intensity(gamma, radians(j)));
    }
  sphere.lower_radius_m = max_lower ? sphere.radius_m : radius(other);
  sphere.upper_radius_m = max_lower ? radius(other) : sphere.radius_m;
  return sphere;
}

Figures compute_figures(const Distribution& distribution, const FigureOptions& options) {
  Figures figures;
  figures.lumens = distribution.flux();
  figures.max_candela = distribution.max_intensity();
  figures.max_direction = distribution.max_direction();
  figures.symmetry = distribution.symmetry();
  // The two great circles through the direction of maximum intensity: one through the
  // axis, one across it (for a maximum on the axis: the C0-C180 and C90-C270 planes).
  const Vec3d axis{0, 0, 1}, c0{1, 0, 0};
  const Vec3d peak = world_direction(axis, c0, figures.max_direction);
  Vec3d through{1, 0, 0};
  const double sideways = std::hypot(peak[0], peak[1]);
  if (sideways > 0 && figures.max_direction.gamma > 0) {
    // the unit tangent at peak toward the axis's great circle: (axis - (axis.peak) peak)
    const double along = peak[2];
    through = {-along * peak[0] / sideways, -along * peak[1] / sideways, sideways};
  }
  const Vec3d across{peak[1] * through[2] - peak[2] * through[1],
                     peak[2] * through[0] - peak[0] * through[2],
                     peak[0] * through[1] - peak[1] * through[0]};
  figures.beam_planes_deg = {arc_angle(distribution, peak, through, 0.5 * figures.max_candela),
                             arc_angle(distribution, peak, across, 0.5 * figures.max_candela)};
  figures.field_planes_deg = {arc_angle(distribution, peak, through, 0.1 * figures.max_candela),
                              arc_angle(distribution, peak, across, 0.1 * figures.max_candela)};
  figures.beam_angle_deg = 0.5 * (figures.beam_planes_deg[0] + figures.beam_planes_deg[1]);
  figures.field_angle_deg = 0.5 * (figures.field_planes_deg[0] + figures.field_planes_deg[1]);
  figures.partial_sphere = partial_sphere(distribution, options);
  return figures;
}

}  // namespace penumbra::photometry
