#include "penumbra/basis/direct_lighting.h"

#include "penumbra/base/parallel.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/basis/spherical_harmonics.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/scene/scene.h"

namespace penumbra::basis {

using namespace vector_ops;

namespace {

// runs compute(i) for every patch, in parallel when asked, reporting each to progress.
void for_each_patch(std::size_t count, bool parallel,
                    const std::function<void(std::size_t)>& progress,
                    const std::function<void(std::size_t)>& compute) {
  for_each_index(count, parallel, [&](std::size_t i) {
    compute(i);
    if (progress) progress(1);
  });
}

}  // namespace

std::vector<LightColumns> light_columns(const Scene& scene,
                                        const std::function<int(std::size_t light)>& degree_of) {
  std::vector<LightColumns> layout;
  Eigen::Index next = 0;
  for (std::size_t k = 0; k < scene.lights.size(); ++k) {
    const Light& light = scene.lights[k];
    LightColumns columns;
    columns.name = light.name;
    columns.first_column = next;
    if (std::holds_alternative<PointLight>(light.source)) {
      columns.kind = LightKind::point;
      columns.degree = degree_of(k);
      columns.count = sh_count(columns.degree);
    } else {
      columns.kind = std::holds_alternative<LinearLight>(light.source) ? LightKind::linear
                     : std::holds_alternative<AreaLight>(light.source) ? LightKind::area
                                                                       : LightKind::directional;
    }
    next += columns.count;
    layout.push_back(columns);
  }
  return layout;
}

const char* kind_name(LightKind kind) {
  switch (kind) {
    case LightKind::point:
      return "point";
    case LightKind::linear:
      return "linear";
    case LightKind::area:
      return "area";
    case LightKind::directional:
      break;
  }
  return "directional";
}

Eigen::MatrixXd direct_illuminance(const Scene& scene, const PatchMesh& mesh,
                                   const std::vector<LightColumns>& layout, bool parallel,
                                   const std::function<void(std::size_t)>& progress) {
  // G_i of eq. (15) is the illuminance of a 1 cd isotropic lamp in the light's place, with
  // exact visibility: the same solver as `penumbra illuminance`, lamps made isotropic.
  Scene isotropic = scene;
  for (Light& light : isotropic.lights)
    if (auto* lamp = std::get_if<PointLight>(&light.source))
      lamp->distribution = photometry::make_isotropic(1);
  const illuminance::IlluminanceSolver solver(isotropic);
  const Eigen::Index columns =
      layout.empty() ? 0 : layout.back().first_column + layout.back().count;
  Eigen::MatrixXd direct = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(mesh.size()), columns);
  for_each_patch(mesh.size(), parallel, progress, [&](std::size_t i) {
    const Patch& patch = mesh.patches()[i];
    const auto row = static_cast<Eigen::Index>(i);
    for (std::size_t k = 0; k < layout.size(); ++k) {
      const LightColumns& light = layout[k];
      const double value = solver.light_at(k, patch.centre, patch.normal);
      if (light.kind != LightKind::point) {
        direct(row, light.first_column) = value;
        continue;
      }
      if (value == 0) continue;
      const Vec3d& position = std::get<PointLight>(scene.lights[k].source).position;
      const Vec3d w = patch.centre - position;
      direct.block(row, light.first_column, 1, light.count) =
          value *
          real_spherical_harmonics(light.degree, Eigen::Vector3d(w[0], w[1], w[2])).transpose();
    }
  });
  return direct;
}

Eigen::MatrixXd exact_direct_illuminance(const Scene& scene, const PatchMesh& mesh, bool parallel,
                                         const std::function<void(std::size_t)>& progress) {
  const illuminance::IlluminanceSolver solver(scene);
  Eigen::MatrixXd direct(static_cast<Eigen::Index>(mesh.size()),
                         static_cast<Eigen::Index>(scene.lights.size()));
  for_each_patch(mesh.size(), parallel, progress, [&](std::size_t i) {
    const Patch& patch = mesh.patches()[i];
    for (std::size_t k = 0; k < scene.lights.size(); ++k)
      direct(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
          solver.light_at(k, patch.centre, patch.normal);
  });
  return direct;
}

}  // namespace penumbra::basis
