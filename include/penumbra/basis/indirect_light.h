#pragma once
// The interreflected part of the light, for display (issue #18; docs/render.md, "Indirect
// light"): what lighting-design tools show, the exact direct light plus the diffuse
// interreflection of a radiosity solve (scene_radiosity.h, Dobashi 1995 eq. 14).
//
// Per patch i and channel c the indirect illuminance is E_total,i,c - E_direct,i (E_total =
// E_direct + F diag(rho) E_total, so it is the light every other patch sends i). At a point
// of a face it is interpolated as the Gouraud display of section 3.5 (step 4) does: vertex
// values are the area-weighted means of the patches that share the vertex
// (PatchMesh::vertex_average), and the point takes the barycentric mean of its triangle in
// the patch's fan. So the value at a point lies between the least and the greatest patch
// value of its patch and of the patches sharing a vertex with it: that is the interpolation
// error bound docs/render.md states, on top of the solve's own discretisation error.

#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "penumbra/base/colour.h"
#include "penumbra/base/vec3d.h"
#include "penumbra/basis/scene_radiosity.h"

namespace penumbra::basis {

class IndirectLight {
 public:
  // keeps solved's mesh and per-patch indirect illuminance (negative rounding clipped to 0).
  explicit IndirectLight(SceneRadiosity solved);

  // returns the indirect illuminance (lux, per channel) at point, a point on (or within
  // rounding of) face `face` of object `object`; {0, 0, 0} when that face has no patch there.
  Colour at(std::size_t object, std::size_t face, const Vec3d& point) const;

  const SceneRadiosity& solution() const { return solved_; }
  const Eigen::MatrixX3d& per_patch() const { return per_patch_; }  // n x 3, lux

 private:
  SceneRadiosity solved_;
  Eigen::MatrixX3d per_patch_;
  Eigen::MatrixX3d per_vertex_;
};

}  // namespace penumbra::basis
