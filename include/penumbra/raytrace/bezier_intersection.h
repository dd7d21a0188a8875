#pragma once
// Rays against bicubic Bézier patches (issue #23; Whitted 1980, section 3). Whitted cuts a
// patch under its bounding sphere until the pieces are small enough to intersect directly;
// here each patch is cut once, before tracing, into pieces whose control points lie within
// a flatness bound of their bilinear corners (the pieces' boxes enter Embree as user
// geometry, embree_scene.h), and a ray that crosses a piece's box is intersected with the
// piece by Newton's method on the exact bicubic in double precision, started from the hit
// on the piece's corner quadrilateral. Normals come from the partial derivatives
// (BezierPatch::normal). docs/bezier-patches.md states the tolerances.

#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/geometry/bezier_patch.h"
#include "penumbra/raytrace/embree_scene.h"

namespace penumbra::raytrace {

// A piece of a patch: its own control points (a sub-patch) and where it lies in the
// patch's parameters.
struct PatchPiece {
  BezierPatch hull;
  double u0, u1, v0, v1;
  std::size_t patch;  // the caller's index of the patch
  Vec3d low, high;    // the box of hull's control points
};

// returns the pieces of patch (numbered patch_index): de Casteljau halves, the longer
// parameter direction first, until flatness() is at most relative_flatness times the
// piece's box diagonal or eight levels are reached.
std::vector<PatchPiece> flat_pieces(const BezierPatch& patch, std::size_t patch_index,
                                    double relative_flatness = 0.02);

// A point of a patch on a ray: the ray parameter and the patch parameters.
struct PatchHit {
  double t, u, v;
};

// returns the hit of ray on the part of patch that piece covers, with t in
// [ray.t_near, ray.t_far], or {} when Newton's method finds none. A hit within 1e-12 of the
// piece's parameter range counts (adjacent pieces and patches may both report a hit on
// their common edge; the nearer wins).
std::optional<PatchHit> intersect_piece(const BezierPatch& patch, const PatchPiece& piece,
                                        const Ray& ray);

// returns the nearest hit of ray on the patch over its pieces, or {}.
std::optional<PatchHit> intersect_patch(const BezierPatch& patch,
                                        const std::vector<PatchPiece>& pieces, const Ray& ray);

}  // namespace penumbra::raytrace
