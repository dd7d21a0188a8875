#pragma once
// The exact planar-face model of a triangle soup (docs/scene-format.md, "Mesh import"):
// equal points merged, degenerate triangles dropped, components oriented consistently
// (closed ones outward), and the triangles of each exact oriented plane united (CGAL
// Polygon_set_2 in the plane's projection) into faces with an outer ring and holes.

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

// returns the planar faces of the soup, adding what it repaired to repairs. Faces come in
// the order of their first triangle. Empty when every triangle is degenerate.
std::vector<PlanarFace> planar_faces(const TriangleSoup& soup, RepairReport& repairs);

}  // namespace penumbra
