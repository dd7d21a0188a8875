#pragma once
// The right-hand sides of the basis radiosity system (Dobashi 1995 eqs. 15-17): the direct
// illuminance of every patch centre for every basis function of every light.
//
// A point light whose distribution is the real spherical harmonic Y_lm (basis/
// spherical_harmonics.h, world frame) gives patch i
//     E_i^(lm) = G_i Y_lm(w_i),   G_i = V_i cos(alpha_i) / r_i^2            (eq. 15)
// with w_i the unit direction from the light to the patch centre, alpha_i the angle of
// incidence and V_i the exact visibility of the light from the centre
// (illuminance::IlluminanceSolver with the lamp made isotropic at 1 cd, so G_i is exactly
// what it returns). A lamp of world SH coefficients c then gives E_i = sum_lm c_lm E_i^(lm).
// A linear source or the sun is not expanded: it is one column, its own direct
// illuminance (exact visible parts, docs/illuminance.md), which relighting may scale.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Scene;

namespace basis {

class PatchMesh;

enum class LightKind { point, linear, directional, area };

// returns the kind as files name it: "point", "linear", "directional" or "area".
const char* kind_name(LightKind kind);

// Where one light's columns sit among the right-hand sides.
struct LightColumns {
  std::string name;
  LightKind kind = LightKind::point;
  int degree = -1;                // point lights: SH degree N; others -1
  Eigen::Index first_column = 0;  // its columns: first_column .. first_column + count - 1
  Eigen::Index count = 1;         // (N + 1)^2 for a point light, 1 otherwise
};

// returns the column layout: the lights of scene in order, point lights with
// degree_of(light index) (>= 0) harmonics, the others one column each.
std::vector<LightColumns> light_columns(const Scene& scene,
                                        const std::function<int(std::size_t light)>& degree_of);

// computes E_direct (n patches x total columns) for the layout. progress, when given, is
// called with the number of patches finished since the last call.
Eigen::MatrixXd direct_illuminance(const Scene& scene, const PatchMesh& mesh,
                                   const std::vector<LightColumns>& layout, bool parallel = true,
                                   const std::function<void(std::size_t)>& progress = {});

// computes the direct illuminance (n patches x lights) of every light of scene with its own
// distribution, at the patch centres, exact visibility: the reference right-hand sides.
Eigen::MatrixXd exact_direct_illuminance(const Scene& scene, const PatchMesh& mesh,
                                         bool parallel = true,
                                         const std::function<void(std::size_t)>& progress = {});

}  // namespace basis
}  // namespace penumbra
