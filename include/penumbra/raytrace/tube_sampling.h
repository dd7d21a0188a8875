#pragma once
// Stratified sampling of a linear (tube) source: elements that act on a receiver as point
// sources (Nishita 1985 eq. (5)). The ray tracer's diffuse term from a tube is exact
// (tube_visibility.h, closed form over the visible pieces); these elements serve Phong's
// highlight, which has no closed form, and the check that stratified shadow rays converge to
// the exact value. See docs/raytrace.md, "Tubes".

#include <cstdint>
#include <functional>
#include <vector>

#include "penumbra/base/vec3d.h"
#include "penumbra/raytrace/tube_visibility.h"

namespace penumbra {

struct LinearLight;

namespace raytrace {

// A piece of a source that acts on the receiver as a point source.
struct SourceElement {
  Vec3d position;  // where it sits on the source
  double candela;  // intensity it sends toward the receiver, after any partial blocking
};

// returns elements of the tube over `pieces`: their total parameter length is cut into
// `samples` strata of equal length laid end to end over the pieces, one point is placed
// uniformly at random in each (random from `seed`), and each element carries
// I sin(theta) dl (Nishita eq. (5): theta the angle between the tube and the direction to the
// receiver, dl the stratum's length in metres) times its piece's `passed`. The sum of
// candela cos(alpha) / r^2 over the elements is an unbiased estimate of the illuminance
// from the pieces.
std::vector<SourceElement> sample_tube_stratified(const LinearLight& tube, const Vec3d& receiver,
                                                  const std::vector<TubePiece>& pieces, int samples,
                                                  std::uint64_t seed);

// returns elements over the whole tube, each also times transmittance(position), the
// fraction of light that passes from the element to the receiver (0 when a shadow ray is
// blocked): stratified shadow rays, Whitted's sampling of an extended source.
std::vector<SourceElement> sample_tube_stratified(
    const LinearLight& tube, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance);

}  // namespace raytrace
}  // namespace penumbra
