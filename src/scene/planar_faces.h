#pragma once
// The exact planar-face model of a triangle soup (docs/scene-format.md, "Mesh import"):
// equal points merged, degenerate triangles dropped, components oriented consistently
// (closed ones outward), and the triangles of each exact oriented plane united in the
// plane's projection into faces with an outer ring and holes: from the mesh's edges when
// the triangles tile the faces edge to edge (edge_rings.h), else by CGAL Polygon_set_2.

#include <array>
#include <vector>

#include "penumbra/geometry/exact.h"
#include "penumbra/scene/model_import.h"

namespace penumbra {

struct TriangleSoup {
  std::vector<RationalPoint3> points;       // exact, already placed
  std::vector<std::array<int, 3>> corners;  // indices into points, as wound in the file
  std::vector<int> materials;               // per triangle; faces merge only within one
};

// returns the planar faces of the soup, adding what it repaired to repairs. Planes come in
// the order of their first triangle, the faces of one plane in the order of their outer
// rings' smallest points. Empty when every triangle is degenerate.
std::vector<PlanarFace> planar_faces(const TriangleSoup& soup, RepairReport& repairs);

}  // namespace penumbra
