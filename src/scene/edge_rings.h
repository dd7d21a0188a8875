#pragma once
// The faces of coplanar triangles that tile them edge to edge (docs/scene-format.md,
// "Faces"): the edges no two triangles share run opposite ways are the faces' boundary,
// chained into rings. This is the union of the triangles, found from the mesh's topology
// with a few exact predicates, whenever the rings pass the checks below; otherwise the
// caller unites the triangles geometrically (Polygon_set_2).

#include <array>
#include <optional>
#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra::detail {

struct EdgeRingFace {
  std::vector<int> outer;               // vertex indices, counter-clockwise
  std::vector<std::vector<int>> holes;  // clockwise
  std::size_t triangles = 0;            // triangles inside the face
};

// returns the faces of triangles (vertex indices into points, each counter-clockwise in
// the plane, distinct vertices distinct points), or nothing when the boundary edges do not
// form disjoint simple rings around regions covered once: a directed edge used twice, a
// vertex where the boundary meets itself, rings that cross or touch (triangles overlapping,
// or meeting along part of an edge), or nesting that is not outer, hole, outer, ...
std::optional<std::vector<EdgeRingFace>> edge_ring_faces(
    const std::vector<std::array<int, 3>>& triangles, const std::vector<Point2>& points);

// returns the winding number of the closed ring around q, a point not on it (exact).
int winding_number(const std::vector<Point2>& ring, const Point2& q);

}  // namespace penumbra::detail
