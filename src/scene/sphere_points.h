#pragma once
// The vertices of a sphere's tessellation for the exact engine: `segments`
// meridians and segments / 2 latitude bands, poles included. The points lie on the
// sphere (to double rounding), so the tessellation is inscribed.

#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra::detail {

std::vector<Vec3d> sphere_points(const Vec3d& center, double radius, int segments);

}  // namespace penumbra::detail
