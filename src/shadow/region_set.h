#pragma once
// Exact Boolean operations on sets of rings in a face's frame (CGAL Polygon_set_2,
// aggregated join), returning canonical regions.

#include <vector>

#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns the union of the counter-clockwise rings minus the union of the
// counter-clockwise rings in subtract.
Region2 unite_minus(const std::vector<Ring2>& rings, const std::vector<Ring2>& subtract = {});

// returns true when the interiors of two convex counter-clockwise rings overlap.
bool interiors_overlap(const Ring2& a, const Ring2& b);

}  // namespace penumbra::detail
