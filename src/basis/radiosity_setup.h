#pragma once
// What every radiosity solve of a scene needs first (private to basis/): reflectances
// checked, the patch mesh, the form factors, and the number of colour channels to solve.

#include <Eigen/Core>
#include <chrono>
#include <functional>

#include "penumbra/base/progress.h"
#include "penumbra/basis/basis_luminances.h"

namespace penumbra::basis::detail {

struct RadiositySetup {
  PatchMesh mesh;
  FormFactorMatrix F;
  int channels = 1;  // 1 when every patch reflects its channels equally, else 3
  BasisTimings timings;

  // the reflectances of channel c, one per patch.
  Eigen::VectorXd reflectance(int channel) const;
};

// checks the materials (reflectance x colour below 1, else InputError naming the
// material), cuts the mesh and computes the form factors, with progress on a terminal.
RadiositySetup prepare_radiosity(const Scene& scene, const BasisOptions& options);

// solves channel c of setup for the right-hand sides direct.
RadiosityResult solve_channel(const RadiositySetup& setup, int channel,
                              const Eigen::MatrixXd& direct, const BasisOptions& options);

// returns a callback advancing a terminal progress line.
std::function<void(std::size_t)> progress_of(Progress& progress);

double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace penumbra::basis::detail
