#include "radiosity_setup.h"

#include "penumbra/base/input_error.h"
#include "penumbra/basis/discontinuity_mesh.h"
#include "penumbra/scene/scene.h"

namespace penumbra::basis::detail {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::function<void(std::size_t)> progress_of(Progress& progress) {
  return [&progress](std::size_t steps) { progress.advance(steps); };
}

Eigen::VectorXd RadiositySetup::reflectance(int channel) const {
  Eigen::VectorXd rho(static_cast<Eigen::Index>(mesh.size()));
  for (std::size_t i = 0; i < mesh.size(); ++i)
    rho[static_cast<Eigen::Index>(i)] =
        mesh.patches()[i].reflectance[static_cast<std::size_t>(channel)];
  return rho;
}

RadiositySetup prepare_radiosity(const Scene& scene, const BasisOptions& options) {
  for (const Material& material : scene.materials)
    for (int c = 0; c < 3; ++c)
      if (!(material.reflectance * material.color[static_cast<std::size_t>(c)] < 1))
        throw InputError(scene.file.string(), "materials." + material.name,
                         "radiosity needs reflectance x colour below 1 in every channel");
  RadiositySetup setup;
  auto start = std::chrono::steady_clock::now();
  setup.mesh = PatchMesh::subdivide(
      scene, options.patch_size,
      options.discontinuity ? shadow_breaks(scene, options.parallel) : MeshBreaks{});
  setup.timings.mesh_s = seconds_since(start);
  start = std::chrono::steady_clock::now();
  {
    Progress progress("form factors", setup.mesh.size());
    FormFactorOptions form = options.form_factors;
    form.parallel = options.parallel;
    setup.F = form_factors(scene, setup.mesh, form, progress_of(progress));
  }
  setup.timings.form_factors_s = seconds_since(start);
  bool grey = true;
  for (const Patch& patch : setup.mesh.patches())
    grey = grey && patch.reflectance[0] == patch.reflectance[1] &&
           patch.reflectance[0] == patch.reflectance[2];
  setup.channels = grey ? 1 : 3;
  return setup;
}

RadiosityResult solve_channel(const RadiositySetup& setup, int channel,
                              const Eigen::MatrixXd& direct, const BasisOptions& options) {
  RadiosityOptions radiosity = options.radiosity;
  radiosity.parallel = options.parallel;
  return solve_radiosity(setup.F, setup.reflectance(channel), direct, radiosity);
}

}  // namespace penumbra::basis::detail
