#pragma once
// Occluders a light does not need (docs/shadows.md, "Faces of real models"): the convex
// pieces of a closed mesh part whose outer side is turned strictly away from the light, when
// the light lies outside the part.
//
// Why: let a segment from a point X to a light L outside a closed solid meet the solid. Seen
// from L, the first point of the solid on the ray toward X lies on a face turned toward L
// (for rays through the interior of such a face; other rays are limits of these, and faces
// are closed). So the closed shadows of the faces turned toward L cover the closed shadow of
// the whole solid, and the regularised shadow of a receiver is the same with or without the
// other faces: only the list of occluders a face names can change. A light inside the solid
// (a lamp in a closed room) is the opposite case, so every piece is kept unless the light is
// strictly outside the part's bounding box; the sun always is.
//
// A linear source q1q2 is every point L of the segment at once (Nishita 1985 section 4.1):
// its whole shadow is the union and its umbra the intersection over L of the point shadows,
// joint umbrae included (a point is in the umbra when every L is hidden from it by some
// occluder). A piece turned strictly away from both ends is turned strictly away from every
// L between them (the side of a plane is affine along the segment), and a segment that misses
// the part's box keeps every L outside it, so for each L the argument above holds and the
// sets are the same without the piece.

#include <vector>

#include "penumbra/scene/scene.h"
#include "penumbra/visibility/light_position.h"

namespace penumbra::detail {

// returns, for each object of the scene, 1 when it is such a piece.
std::vector<char> back_pieces(const Scene& scene, const LightPosition& light);

// the same for the linear source q1q2: 1 for the pieces turned strictly away from both ends
// of parts whose bounding box the closed segment misses.
std::vector<char> back_pieces(const Scene& scene, const Point3& q1, const Point3& q2);

}  // namespace penumbra::detail
