#pragma once
// Whether occluders may hide a linear source together anywhere on a face (exact_umbra.cpp,
// the sweep's region W). Where the whole source is hidden and no single occluder hides it,
// one occluder hides the end q1 and another the end q2 (an occluder hiding both ends hides
// the segment between them: it is convex). So the joint umbra lies in the union, over
// ordered pairs a != b, of PS1(a) ∩ PS2(b), the point shadows of the ends on the face
// (Nishita 1985 section 4.2.2). When none of them shares interior points with the face, the
// union has no interior, no open cell of the sweep lies in it, and the sweep can leave out
// the lines that only matter there (docs/linear-shadows.md, "Groups without W").

#include <array>
#include <vector>

#include "convex_ring.h"
#include "pencil.h"

namespace penumbra::detail {

// The point shadow volume of one end of the source by one occluder on a face: the closed
// set where every function is <= 0 (no function: the occluder hides nothing of that end).
using EndShadow = std::vector<FilteredAffine>;

// A convex polygon of the face's frame by the enclosures of its corners (each exact corner
// lies in its box), so the polygon lies in the convex hull of the boxes.
using EnclosedPolygon = std::vector<std::array<Interval, 2>>;

// returns the polygons piece ∩ PS1(a) ∩ PS2(b), for every piece of the face and occluders a
// and b, that share interior points with the face outside every single umbra (umbrae[k];
// label_of finds a point there in an umbra first, and for a = b the set is a's umbra, unless
// the source was clipped to the face's side after the umbrae were made). ends[e][k] is the
// point shadow of end e by occluder k. W's interior lies in their union; none: W has no
// interior on the face.
std::vector<EnclosedPolygon> joint_parts(const FaceRegion& face,
                                         const std::array<std::vector<EndShadow>, 2>& ends,
                                         const std::vector<ConvexRing>& umbrae);

// the box of the polygon's corners' boxes.
std::array<Interval, 2> box_of(const EnclosedPolygon& polygon);

// false when the intervals show that the line (its coefficients enclosed: d x + e y + f)
// misses every polygon, closed: every corner's box lies strictly on one side of it.
bool may_meet(const std::array<Interval, 3>& line, const std::vector<EnclosedPolygon>& polygons);

}  // namespace penumbra::detail
