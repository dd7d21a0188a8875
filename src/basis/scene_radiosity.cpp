#include "penumbra/basis/scene_radiosity.h"

#include "penumbra/scene/scene.h"
#include "radiosity_setup.h"

namespace penumbra::basis {

using namespace detail;

SceneRadiosity solve_scene_radiosity(const Scene& scene, const BasisOptions& options) {
  RadiositySetup setup = prepare_radiosity(scene, options);
  SceneRadiosity result;
  result.timings = setup.timings;
  result.channels = setup.channels;
  result.form_factor_entries = static_cast<std::size_t>(setup.F.nonZeros());
  auto start = std::chrono::steady_clock::now();
  {
    Progress progress("direct light", setup.mesh.size());
    result.direct_per_light =
        exact_direct_illuminance(scene, setup.mesh, options.parallel, progress_of(progress));
  }
  result.timings.direct_s = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const Eigen::MatrixXd direct = result.direct_per_light.rowwise().sum();
  result.total.resize(direct.rows(), 3);
  for (int channel = 0; channel < result.channels; ++channel) {
    const RadiosityResult solved = solve_channel(setup, channel, direct, options);
    result.iterations = std::max(result.iterations, solved.iterations);
    result.total.col(channel) = solved.illuminance.col(0);
  }
  for (int channel = result.channels; channel < 3; ++channel)
    result.total.col(channel) = result.total.col(0);
  result.timings.solve_s = seconds_since(start);
  result.mesh = std::move(setup.mesh);
  return result;
}

}  // namespace penumbra::basis
