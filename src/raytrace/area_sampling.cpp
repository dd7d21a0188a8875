#include "penumbra/raytrace/area_sampling.h"

#include <algorithm>
#include <cmath>

#include "penumbra/base/random.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {

using namespace vector_ops;

std::vector<SourceElement> sample_area_stratified(
    const AreaLight& panel, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance) {
  std::vector<SourceElement> elements;
  const std::vector<Vec3d>& v = panel.vertices;
  const double total = panel.area();
  if (samples <= 0 || total <= 0) return elements;
  SplitMix64 random(seed);
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const Vec3d a = v[i] - v[0], b = v[i + 1] - v[0];
    const Vec3d normal2 = cross(a, b);  // twice the triangle's area vector (emitting side)
    const double area = 0.5 * length(normal2);
    if (area == 0) continue;
    const Vec3d normal = (1 / length(normal2)) * normal2;
    const int k = std::max(1, static_cast<int>(std::lround(std::sqrt(samples * area / total))));
    const double element_area = area / (k * k);
    for (int p = 0; p < k; ++p)
      for (int q = 0; q < k; ++q) {
        const double u = (p + random.uniform()) / k, w = (q + random.uniform()) / k;
        const double root = std::sqrt(u);
        // barycentric (1 - root, root (1 - w), root w) of (v0, v_i, v_i+1)
        const Vec3d position = v[0] + (root * (1 - w)) * a + (root * w) * b;
        const Vec3d to_receiver = receiver - position;
        const double distance = length(to_receiver);
        if (distance == 0) continue;
        double cos_theta = dot(normal, to_receiver) / distance;
        if (panel.two_sided) cos_theta = std::abs(cos_theta);
        if (cos_theta <= 0) continue;
        const double candela = panel.luminance * cos_theta * element_area;
        const double passed = transmittance(position);
        if (passed > 0) elements.push_back({position, candela * passed});
      }
  }
  return elements;
}

}  // namespace penumbra::raytrace
