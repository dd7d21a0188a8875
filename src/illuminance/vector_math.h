#pragma once
// The double-precision vector helpers of include/penumbra/vec3d.h, for the
// illuminance kernels (private).

#include "penumbra/vec3d.h"

namespace penumbra::illuminance::detail {

using V3 = Vec3d;
using namespace penumbra::vector_ops;

inline double norm(const V3& v) { return length(v); }

}  // namespace penumbra::illuminance::detail
