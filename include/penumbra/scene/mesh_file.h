#pragma once
// Wavefront OBJ and OFF polygon meshes, and their split into convex parts: each
// connected component must be convex, verified exactly (docs/scene-format.md).

#include <filesystem>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra {

struct MeshFile {
  std::filesystem::path path;
  std::vector<Point3> vertices;         // exact, as the doubles in the file
  std::vector<std::vector<int>> faces;  // 0-based vertex indices
  std::vector<int> face_lines;          // the line each face was read from
};

// reads an OBJ (.obj) or OFF (.off) file, chosen by extension. Throws InputError
// naming the file and line.
MeshFile read_mesh(const std::filesystem::path& path);

// splits the mesh into connected components (faces sharing a vertex) and returns
// each as an exact convex polyhedron, in canonical order (by smallest vertex).
// A component is convex when every one of its faces lies in the plane of a face of
// its convex hull; otherwise throws InputError naming the offending face's line.
std::vector<ConvexPolyhedron> convex_parts(const MeshFile& mesh);

}  // namespace penumbra
