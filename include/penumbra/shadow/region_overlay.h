#pragma once
// The overlay of many regions of one face: the face cut into the parts that exactly k of
// the regions cover (an arrangement of all their edges, found pair by pair, with a count on
// every face: src/shadow/segment_arrangement.h). Sun-hours (issue 19, docs/sun-hours.md)
// overlays the shadows of the time steps this way, so that every part of a face carries
// its sunlit duration.

#include <cstddef>
#include <vector>

#include "penumbra/shadow/region.h"

namespace penumbra {

// The points of a window that exactly count of the overlaid regions cover.
struct Coverage {
  std::size_t count = 0;
  Region2 region;  // canonical, with area
};

// returns the window cut by coverage: for each count that some part of the window has, the
// part covered by exactly that many of regions, plus base (for regions the caller knows to
// cover the whole window and leaves out); increasing in count, together tiling the window.
// window: outer ring counter-clockwise, holes clockwise, all canonical. regions: canonical
// regions of the window's frame lying inside the window (what lies outside counts nowhere).
// Points on the regions' boundaries belong to the parts on either side: the parts are
// closed sets with disjoint interiors, as every region of DESIGN.md's conventions.
std::vector<Coverage> coverage(const Polygon2& window, const std::vector<const Region2*>& regions,
                               std::size_t base = 0);

// returns the points of a that lie in b (regions of one frame, canonical): the faces of
// their overlay that both hold, exactly (sun-hours' plan regions, docs/sun-hours.md).
Region2 intersection(const Region2& a, const Region2& b);

}  // namespace penumbra
