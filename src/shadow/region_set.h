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

// The exact sets of a face under a linear source (DESIGN.md, "Conventions").
struct ShadowSets {
  Region2 shadow, umbra, penumbra, lit;
};

// returns shadow = the union of shadows, umbra = the union of umbrae, penumbra = shadow -
// umbra and lit = window - shadow, for canonical convex counter-clockwise rings (as
// ring_with_area gives them) inside the convex window: each union is made once (not once per set it
// enters), and a ring that is the whole window makes its union the window without an arrangement.
ShadowSets shadow_sets(const std::vector<Ring2>& shadows, const std::vector<Ring2>& umbrae,
                       const Ring2& window);

// returns the union of regions (each canonical, in one frame).
Region2 unite_regions(const std::vector<Region2>& regions);

// returns the groups of rings whose closures form connected sets (two rings are joined
// when they have a point in common, touching included), each group increasing, the
// groups in the order of their first ring: rings in different groups are strictly apart.
std::vector<std::vector<std::size_t>> touching_groups(const std::vector<Ring2>& rings);

// returns unite_minus(rings) for convex counter-clockwise rings, given their
// touching_groups: each group united on its own (across threads), as unite_and_complement
// unites them, without the lit part.
Region2 unite_groups(const std::vector<Ring2>& rings,
                     const std::vector<std::vector<std::size_t>>& groups);

// returns {unite_minus(rings), unite_minus({window}, rings)} for convex
// counter-clockwise rings inside the convex window (the union of a single ring is that
// ring's convex_region), given their touching_groups: each group is united on its own
// (across threads), and the lit part is the window with the groups' pieces as holes,
// filled back where a piece has holes; only the pieces that touch the window's boundary
// take a Boolean difference. The result is the one the Boolean operations on all rings at
// once give, canonical.
std::pair<Region2, Region2> unite_and_complement(
    const std::vector<Ring2>& rings, const std::vector<std::vector<std::size_t>>& groups,
    const Ring2& window);

// returns true when the interiors of two convex counter-clockwise rings overlap.
bool interiors_overlap(const Ring2& a, const Ring2& b);

// returns true when the interiors of two of the convex counter-clockwise rings overlap
// (pairs whose boxes meet are tested).
bool any_interiors_overlap(const std::vector<Ring2>& rings);

}  // namespace penumbra::detail
