#pragma once
// Helpers of the scene illuminance tests: scenes from JSON snippets, and references computed
// with the exact oracle (exact_oracle.h, not the library).

#include <cmath>
#include <string>

#include "exact_oracle.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

namespace penumbra::test {

using namespace penumbra::illuminance;

inline bool close(double value, double expected, double relative) {
  return std::abs(value - expected) <= relative * std::abs(expected);
}

inline Scene scene_from(const std::string& objects, const std::string& lights) {
  return parse_scene(
      R"({"penumbra": 1, "objects": [)" + objects + R"(], "lights": [)" + lights + "]}",
      fixture("scenes/illuminance-test.json"));
}

// Reference for a linear source: the midpoint rule over `samples` elements of eq. (5),
// I sin(theta) cos(alpha) / r^2 dl, each element counted only when the exact oracle says
// the open segment from P to it meets no occluder (exact_oracle.h, not the library).
inline double reference_linear(const Scene& scene, const LinearLight& tube, const Vec3d& p,
                               const Vec3d& n, int samples) {
  const Vec3d a = tube.start, b = tube.end;
  const Vec3d axis{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    const double u = (k + 0.5) / samples;
    const Vec3d q{a[0] + u * axis[0], a[1] + u * axis[1], a[2] + u * axis[2]};
    const Vec3d d{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], r = std::sqrt(r2);
    const double cos_alpha = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / r;
    if (cos_alpha <= 0) continue;
    const double cos_theta = (d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2]) / (r * length);
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    bool seen = true;
    for (const Object& object : scene.objects)
      seen = seen && !oracle_segment_blocked(object.solid, to_exact(p), to_exact(q));
    if (seen) sum += tube.candela_per_metre * sin_theta * cos_alpha / r2;
  }
  return sum * length / samples;
}

// the illuminance of a single flat rectangle (origin + s u + t v, s, t in [0, 1]) with the
// two-point Gauss-Legendre rule on panels x panels squares: the flux it receives (lm).
inline double flux_on_rectangle(const IlluminanceSolver& solver, const Vec3d& origin,
                                const Vec3d& u, const Vec3d& v, const Vec3d& normal, int panels_u,
                                int panels_v) {
  const double g = 0.5 / std::sqrt(3.0);
  double sum = 0;
  for (int i = 0; i < panels_u; ++i)
    for (int j = 0; j < panels_v; ++j)
      for (double ds : {0.5 - g, 0.5 + g})
        for (double dt : {0.5 - g, 0.5 + g}) {
          const double s = (i + ds) / panels_u, t = (j + dt) / panels_v;
          sum += solver
                     .at({origin[0] + s * u[0] + t * v[0], origin[1] + s * u[1] + t * v[1],
                          origin[2] + s * u[2] + t * v[2]},
                         normal)
                     .total;
        }
  const Vec3d cross{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
  const double area = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
  return sum * area / (4.0 * panels_u * panels_v);
}

}  // namespace penumbra::test
