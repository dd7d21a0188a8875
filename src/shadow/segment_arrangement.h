#pragma once
// An arrangement of segments made for the overlays of many regions (region_overlay.cpp;
// sun-hours overlays hundreds of shadows on one face), found pair by pair instead of by a
// sweep: the pairs of segments whose boxes meet are classified independently, across
// threads (docs/performance.md, "The pairwise overlay"). Every decision is exact: corners
// and supporting lines are numbered by their exact values, orientations are signs of
// integer expressions (filtered by intervals), crossings come from Cramer's rule in
// integers, and no face is located by an orientation test of its own.

#include <cstddef>
#include <functional>
#include <vector>

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/exact_sum.h"
#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// A segment of a layer's ring, with what it adds to the count on its left (directed from
// its lexicographically smaller end to its larger one): +weight or -weight.
struct LayerSegment {
  Point2 a, b;
  long left = 0;  // added on the left of a->b (a < b lexicographically), subtracted on the right
};

// The arrangement: vertices, edges as halfedge pairs (2e from the smaller vertex to the
// larger, 2e + 1 back), each halfedge's next around the face on its left, and faces.
struct SegmentArrangement {
  std::vector<RationalPoint2> points;  // by vertex
  std::vector<std::size_t> origin;     // by halfedge
  std::vector<std::size_t> next;       // by halfedge
  std::vector<long> left;              // by edge: the count added crossing into 2e's left
  std::vector<std::size_t> face;       // by halfedge: its face (0 is the unbounded face)
  std::vector<long> count;             // by face
  std::size_t faces = 0;
};

// returns the arrangement of segments (each of positive length; exact values in lowest
// terms, as GMP requires of every operand and as arithmetic leaves them: corners are
// numbered by hashes of their limbs), with counts: the unbounded face counts 0, and
// crossing a segment adds its left count on its left.
SegmentArrangement arrange(const std::vector<LayerSegment>& segments);

// Which side a region's rings are traced on, which decides how a region that touches
// itself at a point is written. inside: a polygon is the faces joined across edges, so two
// parts touching at a corner are two polygons, and a hole touching the outer boundary at a
// point is part of that boundary (the overlays of sun-hours, as before with CGAL's
// arrangement). outside: the rings are the boundaries of the faces around the region (keys
// below 0), so two parts touching at a corner are one polygon whose outer boundary touches
// itself, and a hole touching the outer boundary is a hole: what CGAL's Polygon_set_2 gives
// (the union of a face's shadows).
enum class TraceSide { inside, outside };

// The polygons of the faces of one key, and an enclosure of their total area.
struct KeyPolygons {
  long key;
  std::vector<Polygon2> polygons;
  Enclosure area;
};

// returns the polygons of the faces whose key (from their count) is k >= 0, by increasing k:
// the boundaries between keys traced into canonical rings (counter-clockwise outer
// boundaries, clockwise holes) on the given side. Their areas are enclosed from the
// vertices' coordinates, rounded to the enclosures' grid once each.
std::vector<KeyPolygons> polygons_by_count(const SegmentArrangement& arrangement,
                                           const std::function<long(long)>& key,
                                           TraceSide side = TraceSide::inside);

}  // namespace penumbra::detail
