#pragma once
// Bicubic Bézier patches (issue #23; Whitted 1980, section 3), in doubles: evaluation, the
// partial derivatives and the surface normal, de Casteljau subdivision, and the grid a
// tessellation needs for a given tolerance. No geometric decision is taken here: the ray
// tracer intersects patches in double precision (raytrace/bezier_intersection.h) and the
// exact verbs see the tessellation (docs/bezier-patches.md).

#include <array>
#include <utility>

#include "penumbra/base/vec3d.h"

namespace penumbra {

// S(u, v) = sum_i sum_j B_i(u) B_j(v) P_ij for u, v in [0, 1], with the cubic Bernstein
// polynomials B_i(t) = C(3, i) t^i (1 - t)^(3 - i).
struct BezierPatch {
  std::array<Vec3d, 16> points;  // P_ij at index 4 i + j: i runs along u, j along v

  const Vec3d& at(int i, int j) const { return points[static_cast<std::size_t>(4 * i + j)]; }

  // returns S(u, v).
  Vec3d point(double u, double v) const;

  // The surface and its first and mixed derivatives at (u, v).
  struct Jet {
    Vec3d point, du, dv, duv;
  };
  Jet jet(double u, double v) const;

  // returns the unit normal S_u x S_v at (u, v). Where that product vanishes because one
  // edge of the patch collapses to a point (the poles of the teapot's lid and bottom), it
  // returns the limit of the normal as (u, v) approaches the point from inside the patch:
  // on a collapsed edge u = u0, S_v = (u - u0) S_uv + O((u - u0)^2), so the normal tends to
  // the direction of +-S_u x S_uv (likewise in v). The zero vector where no limit is found.
  Vec3d normal(double u, double v) const;

  // the two halves of the patch cut at u = 1/2 (along_u) or v = 1/2, by de Casteljau.
  std::pair<BezierPatch, BezierPatch> split(bool along_u) const;

  // the largest distance of a control point from the bilinear interpolation of the four
  // corners at its parameter (i/3, j/3): zero for a bilinear patch (a flat quadrilateral
  // included); the patch lies within this distance of the bilinear patch (convex hull
  // property of the differences).
  double flatness() const;

  // the axis-aligned box of the control points, which contains the patch.
  std::pair<Vec3d, Vec3d> bounds() const;
};

// returns the smallest n such that the 2 n^2 triangles of the uniform n x n grid of the
// patch (each cell cut along its diagonal from (u_k, v_l) to (u_k+1, v_l+1)) lie within
// tolerance of the patch, by the bound of Filip, Magedson and Markot (1986) for linear
// interpolation on triangles: |S - L| <= (h_u^2 M_uu + 2 h_u h_v M_uv + h_v^2 M_vv) / 8, with
// h = 1/n and M bounding the second derivatives: M_uu <= 6 max |P_(i+2)j - 2 P_(i+1)j + P_ij|,
// M_uv <= 9 max |P_(i+1)(j+1) - P_(i+1)j - P_i(j+1) + P_ij|, M_vv likewise in j. At least 1.
int tessellation_segments(const BezierPatch& patch, double tolerance);

}  // namespace penumbra
