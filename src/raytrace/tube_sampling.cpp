#include "penumbra/raytrace/tube_sampling.h"

#include <algorithm>
#include <cmath>

#include "penumbra/base/random.h"
#include "penumbra/base/vec3d.h"
#include "penumbra/scene/scene.h"

namespace penumbra::raytrace {

using namespace vector_ops;

std::vector<SourceElement> sample_tube_stratified(const LinearLight& tube, const Vec3d& receiver,
                                                  const std::vector<TubePiece>& pieces, int samples,
                                                  std::uint64_t seed) {
  std::vector<SourceElement> elements;
  const Vec3d along = tube.end - tube.start;
  const double tube_length = length(along);
  double total = 0;  // parameter length of the pieces
  for (const TubePiece& piece : pieces) total += piece.high - piece.low;
  if (samples <= 0 || tube_length == 0 || total <= 0) return elements;
  const Vec3d axis = (1 / tube_length) * along;
  const double element_length = tube_length * total / samples;
  SplitMix64 random(seed);
  std::size_t piece = 0;
  double before = 0;  // parameter length of the pieces before `piece`
  for (int k = 0; k < samples; ++k) {
    // The stratum's point, as a parameter length into the pieces laid end to end.
    const double s = total * (k + random.uniform()) / samples;
    while (piece + 1 < pieces.size() && s >= before + (pieces[piece].high - pieces[piece].low)) {
      before += pieces[piece].high - pieces[piece].low;
      ++piece;
    }
    const double u =
        std::clamp(pieces[piece].low + (s - before), pieces[piece].low, pieces[piece].high);
    const Vec3d position = tube.start + u * along;
    const Vec3d to_receiver = receiver - position;
    const double distance = length(to_receiver);
    if (distance == 0) continue;
    // Nishita eq. (5): a Lambertian tube element sends I sin(theta) dl.
    const double cos_theta = dot(axis, to_receiver) / distance;
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const double candela =
        tube.candela_per_metre * sin_theta * element_length * pieces[piece].passed;
    if (candela > 0) elements.push_back({position, candela});
  }
  return elements;
}

std::vector<SourceElement> sample_tube_stratified(
    const LinearLight& tube, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance) {
  std::vector<SourceElement> elements =
      sample_tube_stratified(tube, receiver, {{0, 1, 1}}, samples, seed);
  std::vector<SourceElement> passed;
  for (SourceElement& element : elements) {
    element.candela *= transmittance(element.position);
    if (element.candela > 0) passed.push_back(element);
  }
  return passed;
}

}  // namespace penumbra::raytrace
