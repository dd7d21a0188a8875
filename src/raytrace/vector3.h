#pragma once
// The double-precision vector helpers of include/penumbra/vec3d.h, for the ray tracer
// (magnitudes only; no geometric decision is taken here, DESIGN.md "Exactness").

#include "penumbra/vec3d.h"

namespace penumbra::raytrace {

using Vec3 = Vec3d;
using namespace penumbra::vector_ops;

}  // namespace penumbra::raytrace
