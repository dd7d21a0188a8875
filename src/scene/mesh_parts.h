#pragma once
// The objects a part of a real model becomes (docs/scene-format.md, "Mesh import"): a closed
// convex part is one convex solid, as any "convex" object; every other part (non-convex,
// with holes or handles, or an open surface) becomes the convex pieces of its faces, each a
// two-sided flat polygon object, and the scene's MeshFaces that documents report.

#include <optional>
#include <string>
#include <vector>

#include "penumbra/scene/model_import.h"
#include "penumbra/scene/scene.h"

namespace penumbra::detail {

struct MeshPartObjects {
  std::optional<ConvexPolyhedron> convex;            // a closed convex part
  std::vector<std::vector<ConvexPolyhedron>> faces;  // otherwise, each face's convex pieces
  // and the MeshFaces they make up, in order (a face, then its back for an open one),
  // without part, index and pieces.
  std::vector<MeshFace> mesh_faces;
};

// returns the part's solid when it is a closed convex one, or its faces' convex pieces. Throws
// InputError naming the part when a face cannot be cut (rings that cross).
MeshPartObjects mesh_part_objects(const ModelPart& part, const std::string& file);

// appends to scene the objects of part (named as base, the pieces base.name#k) and, for
// pieces, the MeshFaces they make up.
void add_mesh_part(Scene& scene, const Object& base, const ModelPart& part,
                   MeshPartObjects objects);

// returns "repaired: 3 duplicate vertices merged, ..." listing the repairs that happened, or
// "" when there were none.
std::string repair_summary(const RepairReport& repairs);

}  // namespace penumbra::detail
