#pragma once
// One radiosity solve of a scene as it is lit (Dobashi 1995 eq. 14, Cohen and Greenberg
// 1985): every light with its own distribution, direct illuminance with exact visibility
// (docs/illuminance.md), interreflection by the solver of radiosity.h. This is the
// reference that relighting from basis luminances approximates (`penumbra radiosity`).

#include <Eigen/Core>

#include "penumbra/base/colour.h"

#include "penumbra/basis/basis_luminances.h"

namespace penumbra {
struct Scene;
}

namespace penumbra::basis {

struct SceneRadiosity {
  PatchMesh mesh;
  Eigen::MatrixXd direct_per_light;  // n x lights: E_direct of each light (lux)
  Eigen::MatrixX3d total;            // n x 3: E per channel, all lights (lux)
  int channels = 1;
  int iterations = 0;
  std::size_t form_factor_entries = 0;
  BasisTimings timings;
};

// solves the scene's lighting with options' mesh, form factor and solver settings
// (options.degree and compression are not used).
SceneRadiosity solve_scene_radiosity(const Scene& scene, const BasisOptions& options);

// returns the photometric value of per-channel illuminance (base/colour.h's weights).
inline double photometric(double r, double g, double b) {
  return photometric_value({r, g, b});
}
template <typename Row>
double photometric(const Row& rgb) {
  return photometric(rgb[0], rgb[1], rgb[2]);
}

}  // namespace penumbra::basis
