#include "penumbra/basis/relight.h"

#include <cmath>
#include <stdexcept>

#include "penumbra/basis/distribution_fit.h"
#include "penumbra/basis/sh_rotation.h"
#include "penumbra/basis/spherical_harmonics.h"

namespace penumbra::basis {

using namespace vector_ops;

namespace {

Eigen::Vector3d eigen(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

Lighting default_lighting(const BasisLuminances& basis) {
  Lighting lighting;
  for (const BasisLight& light : basis.lights)
    lighting.push_back({light.coefficients, {1, 1, 1}, 1});
  return lighting;
}

Eigen::VectorXd world_coefficients(const std::vector<double>& legendre_weights, const Vec3d& axis) {
  return zonal_sh_coefficients(legendre_weights, eigen(axis));
}

Eigen::VectorXd world_coefficients(const photometry::Distribution& distribution, int degree,
                                   const Vec3d& axis, const Vec3d& c0, bool sigma) {
  if (is_rotationally_symmetric(distribution)) {
    const LegendreFit fit = fit_legendre(distribution, degree, sigma);
    return world_coefficients(sigma ? fit.series.sigma_smoothed().weights() : fit.series.weights(),
                              axis);
  }
  return rotate_sh(sh_coefficients_of(distribution, degree),
                   photometric_frame(eigen(axis), eigen(c0)));
}

Vec3d reaimed_c0(const Vec3d& axis, const Vec3d& old_c0) {
  const Vec3d a = normalized(axis);
  Vec3d c = old_c0 - dot(old_c0, a) * a;
  if (length(c) < 1e-6) {
    // the old reference is (nearly) along the new axis: take the world axis least aligned
    const Vec3d candidates[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Vec3d* best = &candidates[0];
    for (const Vec3d& candidate : candidates)
      if (std::abs(dot(candidate, a)) < std::abs(dot(*best, a))) best = &candidate;
    c = *best - dot(*best, a) * a;
  }
  return normalized(c);
}

Relit relight(const BasisLuminances& basis, const Lighting& lighting, bool vertices_only) {
  if (lighting.size() != basis.lights.size())
    throw std::invalid_argument("relight: one setting per light is needed");
  const auto patches = static_cast<Eigen::Index>(basis.mesh.size());
  const auto vertices = static_cast<Eigen::Index>(basis.mesh.vertices().size());
  Relit relit;
  relit.vertex_luminance = Eigen::MatrixX3f::Zero(vertices, 3);
  if (!vertices_only) {
    relit.direct = Eigen::MatrixX3f::Zero(patches, 3);
    relit.total = Eigen::MatrixX3f::Zero(patches, 3);
  }
  for (std::size_t k = 0; k < lighting.size(); ++k) {
    const BasisLight& light = basis.lights[k];
    const LightSetting& setting = lighting[k];
    if (setting.coefficients.size() != light.columns.count)
      throw std::invalid_argument("relight: light " + light.columns.name + " needs " +
                                  std::to_string(light.columns.count) + " coefficients");
    const Eigen::VectorXf weights = setting.coefficients.cast<float>();
    const auto scale = static_cast<float>(setting.scale);
    // eq. (18): one weighted sum per stored channel, then the light's colour per channel
    const auto add = [&](const BasisBlock& block, Eigen::Index rows, Eigen::MatrixX3f& out,
                         int channel_of_block) {
      Eigen::VectorXf sum = Eigen::VectorXf::Zero(rows);
      block.accumulate(weights, scale, sum);
      for (int c = 0; c < 3; ++c)
        if (channel_of_block < 0 || channel_of_block == c)
          out.col(c) += static_cast<float>(setting.colour[c]) * sum;
    };
    const bool grey = basis.channels == 1;
    for (int channel = 0; channel < basis.channels; ++channel) {
      const int target = grey ? -1 : channel;
      add(light.vertex_luminance[static_cast<std::size_t>(channel)], vertices,
          relit.vertex_luminance, target);
      if (!vertices_only)
        add(light.total[static_cast<std::size_t>(channel)], patches, relit.total, target);
    }
    if (!vertices_only) add(light.direct, patches, relit.direct, -1);
  }
  return relit;
}

}  // namespace penumbra::basis
