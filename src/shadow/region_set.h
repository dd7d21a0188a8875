#pragma once
// Exact Boolean operations on sets of rings in a face's frame (CGAL Polygon_set_2,
// aggregated join), returning canonical regions.

#include <utility>
#include <vector>

#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns the union of the counter-clockwise rings minus the union of the
// counter-clockwise rings in subtract.
Region2 unite_minus(const std::vector<Ring2>& rings, const std::vector<Ring2>& subtract = {});

// returns {unite_minus(rings), unite_minus({window}, rings)} for convex
// counter-clockwise rings inside the convex window, building the union once (the
// union of a single ring is that ring's convex_region).
std::pair<Region2, Region2> unite_and_complement(const std::vector<Ring2>& rings,
                                                 const Ring2& window);

// returns true when the interiors of two convex counter-clockwise rings overlap.
bool interiors_overlap(const Ring2& a, const Ring2& b);

}  // namespace penumbra::detail
