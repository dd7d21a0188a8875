#include "penumbra/basis/basis_luminances.h"

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/basis/relight.h"
#include "penumbra/scene/scene.h"
#include "radiosity_setup.h"

namespace penumbra::basis {

using namespace detail;

const BasisLight* BasisLuminances::find_light(const std::string& name) const {
  for (const BasisLight& light : lights)
    if (light.columns.name == name) return &light;
  return nullptr;
}

BasisLuminances compute_basis(const Scene& scene, const BasisOptions& options) {
  RadiositySetup setup = prepare_radiosity(scene, options);
  BasisLuminances basis;
  basis.options = options;
  basis.camera = scene.camera;
  basis.scene_file = scene.file.string();
  for (const Object& object : scene.objects) basis.object_names.push_back(object.name);
  basis.timings = setup.timings;
  basis.channels = setup.channels;
  basis.form_factor_entries = static_cast<std::size_t>(setup.F.nonZeros());

  const auto degree_of = [&](std::size_t light) {
    for (const auto& [name, degree] : options.light_degrees)
      if (name == scene.lights[light].name) return degree;
    return options.degree;
  };
  const std::vector<LightColumns> layout = light_columns(scene, degree_of);
  auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd direct;
  {
    Progress progress("direct light", setup.mesh.size());
    direct = direct_illuminance(scene, setup.mesh, layout, options.parallel, progress_of(progress));
  }
  basis.timings.direct_s = seconds_since(start);

  for (const LightColumns& columns : layout) {
    BasisLight light;
    light.columns = columns;
    const Light& source = *scene.find_light(columns.name);
    if (const auto* lamp = std::get_if<PointLight>(&source.source)) {
      light.position = lamp->position;
      light.axis = lamp->axis;
      light.c0 = lamp->c0;
      light.lid = lamp->lid;
      light.lid_base = std::filesystem::absolute(scene.file).parent_path().string();
      light.coefficients = world_coefficients(*lamp->distribution, columns.degree, lamp->axis,
                                              lamp->c0, options.sigma);
    } else {
      light.coefficients = Eigen::VectorXd::Ones(1);
    }
    light.direct = BasisBlock::compressed(
        direct.middleCols(light.columns.first_column, columns.count), options.compression);
    basis.lights.push_back(std::move(light));
  }
  for (int channel = 0; channel < basis.channels; ++channel) {
    start = std::chrono::steady_clock::now();
    const RadiosityResult solved = solve_channel(setup, channel, direct, options);
    basis.iterations = std::max(basis.iterations, solved.iterations);
    basis.timings.solve_s += seconds_since(start);
    start = std::chrono::steady_clock::now();
    // luminance of a diffuse patch: rho E / pi (section 3.4), averaged to the vertices
    const Eigen::MatrixXd luminance =
        setup.reflectance(channel).asDiagonal() * solved.illuminance / pi;
    for (BasisLight& light : basis.lights) {
      const Eigen::Index first = light.columns.first_column, count = light.columns.count;
      light.total.push_back(
          BasisBlock::compressed(solved.illuminance.middleCols(first, count), options.compression));
      light.vertex_luminance.push_back(BasisBlock::compressed(
          setup.mesh.vertex_average(Eigen::MatrixXd(luminance.middleCols(first, count))),
          options.compression));
    }
    basis.timings.compress_s += seconds_since(start);
  }
  basis.mesh = std::move(setup.mesh);
  return basis;
}

}  // namespace penumbra::basis
