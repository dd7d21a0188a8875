#pragma once
// Objects made of bicubic Bézier patches (issue #23, docs/bezier-patches.md): the patch
// file format (.bpt) and the tessellation the exact verbs see, made into a model part so
// that it becomes convex pieces like any real model (mesh_parts.h).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "penumbra/geometry/bezier_patch.h"
#include "penumbra/scene/model_import.h"

namespace penumbra::detail {

// reads a patch file: the number of patches, then per patch its degrees "3 3" and its 16
// control points, one "x y z" per line, P_00 P_01 .. P_03 P_10 .. P_33 (docs/bezier-patches.md).
// Throws InputError naming the file and the line for anything else.
std::vector<BezierPatch> read_bezier_file(const std::filesystem::path& path);

// returns the patches with each control point placed as placement says (scale, up axis,
// transform; a patch is affine invariant, so placing its control points places it).
std::vector<BezierPatch> placed_patches(std::vector<BezierPatch> patches,
                                        const Placement& placement);

// The tessellation of a patch object: one grid size n for all its patches (so that patches
// sharing an edge share its points), the smallest for which every patch's triangles lie
// within tolerance (tessellation_segments), each grid point rounded to the snap grid, the
// triangles made into exact planar faces as a model's are.
struct PatchTessellation {
  ModelPart part;
  int segments = 0;
  std::size_t triangles = 0;  // non-degenerate triangles
};
// returns the grid size n that tessellate uses for patches at tolerance.
int grid_segments(const std::vector<BezierPatch>& patches, double tolerance);

PatchTessellation tessellate(const std::vector<BezierPatch>& patches, double tolerance, double snap,
                             const std::string& name);

}  // namespace penumbra::detail
