#include "sphere_points.h"

#include <cmath>
#include "penumbra/base/numbers.h"

namespace penumbra::detail {

std::vector<Vec3d> sphere_points(const Vec3d& center, double radius, int segments) {
  const int bands = std::max(2, segments / 2);
  std::vector<Vec3d> points;
  points.push_back({center[0], center[1], center[2] + radius});
  points.push_back({center[0], center[1], center[2] - radius});
  for (int i = 1; i < bands; ++i) {
    const double polar = pi * i / bands;
    for (int j = 0; j < segments; ++j) {
      const double azimuth = 2 * pi * j / segments;
      points.push_back({center[0] + radius * std::sin(polar) * std::cos(azimuth),
                        center[1] + radius * std::sin(polar) * std::sin(azimuth),
                        center[2] + radius * std::cos(polar)});
    }
  }
  return points;
}

}  // namespace penumbra::detail
