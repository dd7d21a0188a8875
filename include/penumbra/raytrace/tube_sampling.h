#pragma once
// The ray tracer's linear (tube) sources: a STOPGAP that samples the tube stratified along
// its length and casts one shadow ray per sample. The exact visible-interval code of the
// illuminance layer (Nishita 1985 section 4.2.3) will replace this function: it would
// return quadrature nodes over the visible intervals in the same SourceElement form, so
// the ray tracer's shading does not change. See docs/raytrace.md.

#include "penumbra/vec3d.h"
#include <cstdint>
#include <functional>
#include <vector>

namespace penumbra {

struct LinearLight;

namespace raytrace {

// A piece of a source that acts on the receiver as a point source.
struct SourceElement {
  Vec3d position;  // where it sits on the source
  double candela;  // intensity it sends toward the receiver, after any partial blocking
};

// returns the visible elements of the tube seen from receiver: the tube is cut into
// `samples` strata of equal length, one point is placed uniformly at random in each
// (random from `seed`), and each element carries I sin(theta) dl (Nishita eq. (5):
// theta the angle between the tube and the direction to the receiver, dl = length /
// samples) times transmittance(position), the fraction of light that passes from the
// element to the receiver (0 when a shadow ray is blocked). The sum of
// candela cos(alpha) / r^2 over the elements is an unbiased estimate of the illuminance.
std::vector<SourceElement> sample_tube_stratified(
    const LinearLight& tube, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance);

}  // namespace raytrace
}  // namespace penumbra
