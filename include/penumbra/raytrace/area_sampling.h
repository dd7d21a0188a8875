#pragma once
// Stratified sampling of an area (polygon) source for the ray tracer: elements that act on a
// receiver as point sources, each with its own shadow ray (Whitted's sampling of an extended
// source; docs/raytrace.md, "Area sources"). The exact engine's value is Lambert's closed form
// over the exactly visible part (illuminance/area_source.h); these elements converge to it.

#include <cstdint>
#include <functional>
#include <vector>

#include "penumbra/base/vec3d.h"
#include "penumbra/raytrace/tube_sampling.h"

namespace penumbra {

struct AreaLight;

namespace raytrace {

// returns about `samples` elements of the polygon (a fan of triangles from its first vertex,
// each given samples in proportion to its area, as a k x k jittered grid of the unit square
// mapped onto the triangle by (u, v) -> (1 - sqrt(u), v sqrt(u)), which keeps areas), each
// carrying L cos(theta) dA toward the receiver (theta from the source's normal on the
// receiver's side; 0 behind a one-sided source) times transmittance(position). The sum of
// candela cos(alpha) / r^2 over the elements is an unbiased estimate of the illuminance.
std::vector<SourceElement> sample_area_stratified(
    const AreaLight& panel, const Vec3d& receiver, int samples, std::uint64_t seed,
    const std::function<double(const Vec3d& position)>& transmittance);

}  // namespace raytrace
}  // namespace penumbra
