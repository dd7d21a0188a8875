#include "penumbra/illuminance/area_source.h"

#include <cmath>

namespace penumbra::illuminance {

using namespace vector_ops;

double projected_solid_angle(const Vec3d& point, const Vec3d& normal, const Vec3d* ring,
                             std::size_t count) {
  double sum = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3d a = ring[i] - point;
    const Vec3d b = ring[(i + 1) % count] - point;
    const Vec3d c = cross(b, a);
    const double sine = length(c);  // |a| |b| sin(theta)
    if (sine == 0) continue;        // an edge on a line through P subtends nothing
    // theta by atan2: accurate for small and for nearly straight angles alike.
    const double theta = std::atan2(sine, dot(a, b));
    sum += theta * dot(normal, c) / sine;
  }
  return 0.5 * sum;
}

double projected_solid_angle(const Vec3d& point, const Vec3d& normal,
                             const std::vector<std::vector<Vec3d>>& rings) {
  double sum = 0;
  for (const std::vector<Vec3d>& ring : rings)
    sum += projected_solid_angle(point, normal, ring.data(), ring.size());
  return sum;
}

}  // namespace penumbra::illuminance
