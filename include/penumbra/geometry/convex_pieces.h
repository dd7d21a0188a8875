#pragma once
// A planar polygon with holes cut into convex pieces (docs/scene-format.md, "Mesh
// import"): the faces of real models are often non-convex and have holes, while the shadow
// engine's occluders and receivers are convex. The face is triangulated with its rings as
// constraints (CGAL's constrained Delaunay triangulation, exact) and the triangles are merged
// greedily across diagonals while the union stays convex (Hertel and Mehlhorn 1983: at most
// four times the minimum number of pieces). No point is added: every piece's vertices are
// vertices of the rings.

#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra {

// returns convex pieces whose union is the polygon on plane bounded by outer
// (counter-clockwise seen from plane's positive side) less the holes (clockwise), their
// interiors disjoint, each counter-clockwise seen from the positive side. Every ring point
// must lie on plane; rings must not cross (they may touch at points). The pieces and their
// order depend only on the polygon: not on where its rings start nor on the holes' order.
std::vector<std::vector<Point3>> convex_pieces(const Plane3& plane,
                                               const std::vector<Point3>& outer,
                                               const std::vector<std::vector<Point3>>& holes);

}  // namespace penumbra
