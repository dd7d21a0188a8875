#pragma once
// The inverse problem (beyond the paper, its section 6): the distribution of one point
// lamp that best produces target illuminances on chosen patches, other lights as set.
//
// The unknowns are the intensities I_k >= 0 at control angles gamma_k = k pi / K about the
// lamp's axis, joined linearly (the curve of the editor of section 4.1). The Legendre
// weights are linear in them, w = T I (T_lk: the weights of the k-th hat function, eq. 3
// by Gauss-Legendre), the world SH coefficients are c = Z sigma w (eq. 10) and the total
// illuminance of patch p is E_p = E_other,p + sum_j B_pj c_j (eq. 18). So
// min |E - target| over I >= 0 is a non-negative least-squares problem in K + 1 unknowns.

#include <cstdint>
#include <vector>

#include "penumbra/basis/relight.h"

namespace penumbra::basis {

struct FitTarget {
  std::uint32_t patch;  // index into the mesh
  double illuminance;   // lux wanted there (total: direct and interreflected)
};

struct DistributionFit {
  std::vector<double> angles_deg;  // control angles, 0 .. 180
  std::vector<double> candela;     // fitted intensities, >= 0
  std::vector<double> weights;     // the Legendre weights w_l (without sigma factors)
  LightSetting setting;            // the lamp's setting with the fitted distribution
  std::vector<double> achieved;    // E at each target with the fit (lux)
  double rms_residual = 0;         // lux
  double max_residual = 0;         // lux
};

// fits light (index; a point light) of basis aimed along axis (unit), with the other
// lights as in lighting (the entry of light itself is ignored but for its colour and
// scale), using intervals + 1 control points. Throws std::invalid_argument for a light
// that is not a point light or no targets.
DistributionFit fit_distribution(const BasisLuminances& basis, const Lighting& lighting,
                                 std::size_t light, const Vec3d& axis,
                                 const std::vector<FitTarget>& targets, int intervals, bool sigma);

}  // namespace penumbra::basis
