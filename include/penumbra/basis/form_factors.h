#pragma once
// Form factors between patches (Dobashi 1995 eq. 14; Cohen and Greenberg 1985), computed
// once per scene and shared by every right-hand side (section 3.4).
//
// F_ij is the fraction of the light leaving patch i diffusely that arrives at patch j
// directly: F_ij = 1/A_i int_{A_i} int_{A_j} V cos(t_i) cos(t_j) / (pi r^2) dA_j dA_i.
// Two methods (docs/basis.md, "Form factors"):
// - rays (default): K rays leave each patch from points stratified over its area, in
//   cosine-weighted directions stratified over the hemisphere (Malley's method: a
//   stratified point of the unit disk lifted to the hemisphere); the patch each ray hits
//   first (Embree, raytrace/embree_scene.h) gets 1/K. Unbiased for the area-averaged
//   form factor, visibility included; row sums are the fraction of rays that hit
//   something (exactly 1 in a closed room). Cost O(n K), memory O(n K).
// - analytic: from the centre of patch i, the point-to-polygon form factor of every patch
//   j (Lambert's contour integral, point_polygon_form_factor) times the visibility of
//   j's centre (one Embree ray). Exact for unoccluded pairs as the patches shrink
//   (O(h^2) in the patch size); O(n^2) time, for small scenes and for checking.

#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <vector>

#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Scene;

namespace basis {

class PatchMesh;

enum class FormFactorMethod { rays, analytic };

struct FormFactorOptions {
  FormFactorMethod method = FormFactorMethod::rays;
  int rays = 1024;         // rays per patch (rounded down to a square, at least 1)
  std::uint64_t seed = 1;  // the patch index is mixed in: results do not depend on threads
  bool parallel = true;    // TBB over patches
};

// n x n, row i holds F_ij. Row-major sparse: the solver gathers along rows.
using FormFactorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int64_t>;

// computes the form factors of mesh (built from scene). progress, when given, is called
// with the number of patches finished since the last call (from any thread).
FormFactorMatrix form_factors(const Scene& scene, const PatchMesh& mesh,
                              const FormFactorOptions& options,
                              const std::function<void(std::size_t)>& progress = {});

// returns the form factor from a differential area at point with unit normal to the
// planar polygon (vertices counter-clockwise seen from the side that receives, i.e. from
// the point), unoccluded: (1 / 2 pi) sum_k gamma_k n . (R_k x R_{k+1}) / |R_k x R_{k+1}|,
// R_k the unit vectors toward the vertices and gamma_k the angle between R_k and R_{k+1}
// (Lambert 1760; Baum, Rushmeier and Winget 1989 eq. 3). The polygon must lie wholly in
// front of the point's tangent plane.
double point_polygon_form_factor(const Vec3d& point, const Vec3d& normal,
                                 const std::vector<Vec3d>& polygon);

}  // namespace basis
}  // namespace penumbra
