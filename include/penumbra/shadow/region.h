#pragma once
// Exact polygon sets in a face's 2D frame, the form in which shadow and lit parts
// of a face are reported (DESIGN.md, "Conventions"): outer boundaries
// counter-clockwise, holes clockwise, every ring in canonical form (no repeated or
// collinear vertices, starting at its lexicographically smallest vertex), polygons
// sorted, so that equal sets have equal representations.

#include <optional>
#include <vector>

#include "penumbra/geometry/exact_sum.h"
#include "penumbra/geometry/kernel.h"

namespace penumbra {

using Ring2 = std::vector<Point2>;

struct Polygon2 {
  Ring2 outer;               // counter-clockwise
  std::vector<Ring2> holes;  // clockwise

  bool operator==(const Polygon2& other) const {
    return outer == other.outer && holes == other.holes;
  }
};

struct Region2 {
  std::vector<Polygon2> polygons;
  Exact area = 0;  // in frame units (s, t); world area = area * |u| |v|

  bool empty() const { return polygons.empty(); }
  bool operator==(const Region2& other) const { return polygons == other.polygons; }
};

// returns the signed area of a ring (positive when counter-clockwise), exactly.
Exact signed_area(const Ring2& ring);

// returns the sign of signed_area(ring): from the shoelace sum in intervals when they decide
// it (then it is the exact sign), otherwise from the exact area.
CGAL::Sign area_sign(const Ring2& ring);

// returns ring without repeated and collinear vertices, rotated to start at its
// lexicographically smallest vertex (orientation kept); a ring that touches itself there
// starts at the pass whose following vertices are lexicographically smallest. Empty when
// nothing with area is left.
Ring2 canonical_ring(const Ring2& ring);

// sorts holes and polygons and fills area: the canonical form of a region whose
// rings are already canonical. area, when given, is the region's area known otherwise
// (the window's less its complement's: the same exact value, without summing the rings).
Region2 canonical_region(std::vector<Polygon2> polygons, std::optional<Exact> area = {});

// the same, with an enclosure of the polygons' total area found ahead (an overlay's, from its
// vertices once each): the exact area is computed from the rings when first asked for.
Region2 canonical_region(std::vector<Polygon2> polygons, const Enclosure& area);

// returns an enclosure of the area of polygon (outer boundary less holes), in integers
// (exact_sum.h), its long rings summed in runs across threads.
Enclosure area_enclosure(const Polygon2& polygon);

// returns a region holding the single convex polygon ring (counter-clockwise).
Region2 convex_region(const Ring2& ring);

}  // namespace penumbra
