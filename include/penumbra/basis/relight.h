#pragma once
// Relighting from basis luminances (Dobashi 1995 section 3.5, eq. 18): a lighting is, per
// light, the world SH coefficients of its distribution (or a scale for a linear source or
// the sun) and a colour; patch illuminance and vertex luminance are weighted sums of the
// stored basis values, no radiosity solve.
//
//   E_i = sum_lights colour x scale x sum_k c_k E_i^(k)                      (eq. 18)
//   c   = sigma(N, l) w_l A_lm(axis)  for a rotationally symmetric lamp (eq. 10),
//         the rotated SH coefficients of the full distribution otherwise.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "penumbra/base/colour.h"
#include "penumbra/basis/basis_luminances.h"

namespace penumbra::photometry {
class Distribution;
}

namespace penumbra::basis {

struct LightSetting {
  Eigen::VectorXd coefficients;  // world SH coefficients (point) or [1]
  Colour colour{1, 1, 1};
  double scale = 1;  // dimming
};

// One setting per light of the basis, in its order.
using Lighting = std::vector<LightSetting>;

// returns the lighting the scene was computed with (each light's own distribution).
Lighting default_lighting(const BasisLuminances& basis);

// returns the world SH coefficients, of degree <= degree, of distribution aimed along axis
// with its C = 0 plane toward c0 (unit, orthogonal): the Legendre weights (with sigma
// factors when sigma) about the axis for a rotationally symmetric distribution, the
// rotated SH coefficients otherwise.
Eigen::VectorXd world_coefficients(const photometry::Distribution& distribution, int degree,
                                   const Vec3d& axis, const Vec3d& c0, bool sigma);

// returns the world SH coefficients of the rotationally symmetric series with Legendre
// weights w_0..w_N (sigma factors already applied or not) about axis.
Eigen::VectorXd world_coefficients(const std::vector<double>& legendre_weights, const Vec3d& axis);

// returns c0 for a lamp re-aimed to axis: the old c0 made orthogonal to the new axis, or
// any unit vector orthogonal to it when the old one is parallel.
Vec3d reaimed_c0(const Vec3d& axis, const Vec3d& old_c0);

struct Relit {
  // per patch: direct and total illuminance (lux), per channel (n x 3)
  Eigen::MatrixX3f direct, total;
  // per vertex: luminance (cd/m^2) per channel (vertices x 3), Gouraud values
  Eigen::MatrixX3f vertex_luminance;
};

// recombines the basis values for lighting (one setting per light). With
// vertices_only, only vertex_luminance is filled (what an interactive view needs).
// Throws std::invalid_argument when a setting's size does not match its light.
Relit relight(const BasisLuminances& basis, const Lighting& lighting, bool vertices_only = false);

}  // namespace penumbra::basis
