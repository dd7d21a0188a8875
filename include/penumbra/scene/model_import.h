#pragma once
// Real CAD and 3D models read through Assimp into an exact model of planar faces
// (issue #14, docs/scene-format.md, "Mesh import"): every node of the file that carries
// meshes becomes a named part; the file's coordinates are placed exactly (node transforms,
// scale, up axis, transform), after one documented rounding (the snap grid); adjacent
// triangles lying exactly in one plane merge into one face, which may be non-convex and
// have holes. Assimp stays behind this header.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/geometry/kernel.h"

namespace penumbra {

// How the file's coordinates become world coordinates (docs/scene-format.md, "Placement"):
// in order, the file's node transforms, `scale`, the snap grid, the up-axis turn and
// `transform`; every step but the snap is exact.
struct Placement {
  // the file's up axis is +Y: (x, y, z) turns to (x, -z, y), a rotation about +X taking +Y to +Z.
  bool y_up = false;
  // file units to metres (0.001 for millimetres); finite and positive.
  double scale = 1;
  // a 4 x 4 row-major matrix applied to column vectors (x, y, z, 1); its last row must be
  // (0, 0, 0, 1) and its 3 x 3 part invertible.
  std::optional<std::array<double, 16>> transform;
  // the grid, in metres, each scaled coordinate is rounded to (ties away from zero); 0 = off.
  // Read as the shortest decimal that rounds to this double (1e-6 is exactly 1/1000000).
  double snap = 1e-6;
};

// A planar polygon with holes, exact: one connected piece of the union of a part's triangles
// lying in one oriented plane (with one material). Seen from the side its plane's normal
// points to (outside), the outer ring runs counter-clockwise and each hole clockwise; no
// ring has two consecutive equal points or three consecutive collinear ones. Rings do not
// cross, but a hole may touch the outer ring or another hole at a point.
struct PlanarFace {
  Plane3 plane;  // positive side = outside; every ring point lies on it exactly
  std::vector<Point3> outer;
  std::vector<std::vector<Point3>> holes;
  int material = -1;  // index into ImportedModel::materials, -1 for none
  // the face lies on a closed, consistently oriented component (a solid), so its normal
  // points out of the solid; false on an open surface, whose normal follows the file.
  bool solid = false;
  std::size_t triangles = 0;  // how many of the file's triangles merged into it
};

// What the importer repaired or left out, in counts (docs/scene-format.md, "Repairs").
struct RepairReport {
  std::size_t snapped_coordinates_changed = 0;  // coordinates the snap grid moved
  std::size_t duplicate_vertices_merged = 0;    // vertices equal (after snapping) to another
  std::size_t degenerate_faces_dropped = 0;     // triangles with < 3 distinct or collinear points
  std::size_t non_surface_primitives_ignored = 0;  // points and lines of the file
  std::size_t components_reoriented = 0;  // components with triangles turned to agree / face out
  std::size_t closed_components = 0;      // components bounding a volume
  std::size_t open_components = 0;        // open surfaces (or non-manifold components)
  std::size_t non_manifold_edges = 0;     // edges shared by more than two triangles
  // faces where triangles of one plane overlapped: the face covers the overlap once, so its
  // area is less than the sum of its triangles'.
  std::size_t overlapping_faces = 0;

  RepairReport& operator+=(const RepairReport& other);
};

struct ModelMaterial {
  std::string name;
  std::optional<std::array<double, 3>> colour;  // diffuse RGB in [0, 1], when the file has one
};

struct ModelPart {
  std::string name;  // unique within the model (docs/scene-format.md, "Part names")
  std::vector<PlanarFace> faces;
  // the diffuse colour when every face of the part has the same one.
  std::optional<std::array<double, 3>> colour;
  RepairReport repairs;
};

struct ImportedModel {
  std::vector<ModelPart> parts;  // in the file's node order (depth first)
  std::vector<ModelMaterial> materials;
  RepairReport repairs;  // the sum over the parts
};

// The most faces (triangles once triangulated) a model may have, counting each use of a mesh
// by the file's nodes (docs/reliability.md, "Limits").
inline constexpr std::uint64_t max_model_faces = 10'000'000;

// reads the model file at path through Assimp and returns its exact planar-face model,
// placed as placement says. Throws InputError naming the file (and the part, where one is
// concerned) for a missing or unreadable file, a format Assimp does not read, a
// coordinate that is not finite, a part none of whose faces survives snapping, a file
// without faces, or an invalid placement. Parts are built across threads when parallel;
// the result is the same either way.
ImportedModel import_model(const std::filesystem::path& path, const Placement& placement = {},
                           bool parallel = true);

}  // namespace penumbra
