#pragma once
// The double-precision vector helpers of include/penumbra/vec3d.h, for the renderer
// (private; magnitudes and image-space positions only).

#include "penumbra/vec3d.h"

namespace penumbra::render::detail {

using V3 = Vec3d;
using namespace penumbra::vector_ops;

inline double norm(const V3& v) { return length(v); }

}  // namespace penumbra::render::detail
