#pragma once
// What a point sees of an area source (docs/area-sources.md, "Illuminance"): the part of the
// source's emitting face strictly on the outer side of the receiving plane, minus the shadow
// each occluder casts on the source from the point. That shadow is the one of
// shadow_polygon.h with the point as a point light and the source as the receiving face (the
// relation "the open segment from X to the light meets V" is symmetric), so it is exact, and
// so is the difference.

#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/region.h"

namespace penumbra {

// returns the visible part of source (a face of a flat polygon, the side turned toward
// point) seen from point on a surface whose outer side is receiving.oriented_side() ==
// ON_POSITIVE_SIDE, as oriented rings in source's frame whose signed sum is that part: each
// counter-clockwise ring counts once, each clockwise ring is taken away (the visible part
// P minus hidden convex parts H_i is P - sum H_i + sum H_i ∩ H_j - ..., by inclusion and
// exclusion over the intersections that are not empty; when they are too many, the exact
// Boolean difference, outer rings and holes). Empty when point is not strictly on source's
// positive side or sees none of it. occluders: every solid that may hide part of it (a
// superset is fine). A measure over the region (an area, Lambert's edge sum) is the signed
// sum of its values on the rings.
std::vector<Ring2> visible_source(const Face& source, const Point3& point, const Plane3& receiving,
                                  const std::vector<const ConvexPolyhedron*>& occluders);

}  // namespace penumbra
