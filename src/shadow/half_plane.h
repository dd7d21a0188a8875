#pragma once
// Sections of half-spaces by a face's plane, as half-planes of the face's frame,
// and exact clipping of convex rings by them (Sutherland-Hodgman).

#include <optional>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// The half-plane A s + B t + C < 0 (open) or <= 0 (closed) of frame coordinates.
struct HalfPlane {
  Exact a, b, c;
};

// restricts the half-space plane(X) < 0 to the face's plane, X = o + s u + t v.
HalfPlane restrict_to(const Plane3& plane, const FaceFrame& frame);

// clips a convex ring to the closed half-plane. A half-plane parallel to the face
// (a = b = 0) is constant on it: the open condition c < 0 keeps all or nothing.
Ring2 clip(const Ring2& ring, const HalfPlane& half);

// returns the canonical form of a counter-clockwise ring, or nullopt when it has no area.
std::optional<Ring2> ring_with_area(const Ring2& ring);

// clips a convex ring to the closed convex counter-clockwise ring window.
Ring2 clip_to_convex(Ring2 ring, const Ring2& window);

}  // namespace penumbra::detail
