#pragma once
// The lit part of a face whose shadow polygons are strictly apart (Nishita 1985
// section 3.2: the face minus the union of the shadows cast on it), without
// building an arrangement. Where each polygon meets the window's boundary only
// along segments, the difference is bounded by arcs of the window's boundary and
// the polygons' chords through its interior, walked in turn; a single polygon
// inside the window is a hole. Those are the faces Polygon_set_2 would report. Other
// configurations (a lone vertex on the boundary, holes beside other polygons) are
// left to Polygon_set_2. All decisions are exact.

#include <optional>
#include <vector>

#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns true when the convex polygons a and b have no point in common.
bool strictly_apart(const Ring2& a, const Ring2& b);

// returns window minus the polygons as a canonical region, or nullopt for the
// configurations left to Polygon_set_2. window and polygons are canonical, convex
// and counter-clockwise; the polygons lie in window, are strictly apart and are
// not window itself.
std::optional<Region2> convex_difference(const Ring2& window, const std::vector<Ring2>& polygons);

}  // namespace penumbra::detail
