#include "penumbra/raytrace/tube_sampling.h"

#include <cmath>

#include "penumbra/scene/scene.h"
#include "random.h"
#include "vector3.h"

namespace penumbra::raytrace {

std::vector<SourceElement> sample_tube_stratified(
    const LinearLight& tube, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance) {
  std::vector<SourceElement> elements;
  const Vec3 along = tube.end - tube.start;
  const double tube_length = length(along);
  if (samples <= 0 || tube_length == 0) return elements;
  const Vec3 axis = (1 / tube_length) * along;
  const double element_length = tube_length / samples;
  Random random(seed);
  for (int k = 0; k < samples; ++k) {
    const double u = (k + random.uniform()) / samples;
    const Vec3 position = tube.start + u * along;
    const Vec3 to_receiver = receiver - position;
    const double distance = length(to_receiver);
    if (distance == 0) continue;
    // Nishita eq. (5): a Lambertian tube element sends I sin(theta) dl.
    const double cos_theta = dot(axis, to_receiver) / distance;
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const double candela = tube.candela_per_metre * sin_theta * element_length;
    if (candela == 0) continue;
    const double passed = transmittance(position);
    if (passed > 0) elements.push_back({position, candela * passed});
  }
  return elements;
}

}  // namespace penumbra::raytrace
