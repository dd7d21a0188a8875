#pragma once
// The shadow one convex occluder casts on one face from a point or directional
// source: Nishita 1985 section 3.2, object-space formulation. The shadow volume of
// V is bounded by the pyramid from the source through V's contour (silhouette)
// edges and by V's faces turned toward the source; its section by the face's plane,
// clipped to the face, is a convex polygon (docs/shadows.md derives it).
//
// Definition (the one the oracle tests check): a point X of the face is in the
// shadow of V when the open segment from X to the source (the open ray toward the
// sun) meets V's interior; for a two-sided polygon V, when it crosses V's plane at a
// single point of V's relative interior. The polygon returned is the closure of
// that open set; a shadow without area is no shadow.

#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/region.h"
#include "penumbra/visibility/light_position.h"

namespace penumbra {

// returns true when the source is not strictly on the outer side of the face's
// plane: the face is wholly unlit by it (grazing light included; DESIGN.md).
bool faces_away(const Face& face, const LightPosition& light);

// returns the shadow of occluder on receiver, a convex counter-clockwise canonical
// ring in receiver's frame, or nullopt when it has no area. The receiver must not
// face away from the light, and must not be a face of occluder.
std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder, const Face& receiver,
                                    const LightPosition& light);

// returns the planes of occluder's open shadow volume from light (section 3.2): a
// point X is shadowed when plane(X) < 0 for each. Independent of the receiver, so
// a scene computes it once per occluder and light.
std::vector<Plane3> shadow_volume(const ConvexPolyhedron& occluder, const LightPosition& light);

// returns the shadow polygon for a volume from shadow_volume(occluder, light).
std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder,
                                    const std::vector<Plane3>& volume, const Face& receiver);

}  // namespace penumbra
