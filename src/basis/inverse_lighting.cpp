#include "penumbra/basis/inverse_lighting.h"

#include <cmath>
#include <stdexcept>

#include "penumbra/base/numbers.h"
#include "penumbra/basis/legendre_series.h"
#include "penumbra/basis/nonnegative_least_squares.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/basis/sigma_factors.h"

namespace penumbra::basis {

DistributionFit fit_distribution(const BasisLuminances& basis, const Lighting& lighting,
                                 std::size_t light, const Vec3d& axis,
                                 const std::vector<FitTarget>& targets, int intervals, bool sigma) {
  const BasisLight& lamp = basis.lights.at(light);
  if (lamp.columns.kind != LightKind::point) throw std::invalid_argument("fit: not a point light");
  if (targets.empty()) throw std::invalid_argument("fit: no targets");
  if (intervals < 1) throw std::invalid_argument("fit: at least one interval");
  const int degree = lamp.columns.degree;
  const auto rows = static_cast<Eigen::Index>(targets.size());

  // the other lights' contribution at the targets (grey: channel 0 with the light's colour)
  Lighting others = lighting;
  others[light].scale = 0;
  const Relit rest = relight(basis, others);
  Eigen::VectorXd rhs(rows);
  for (Eigen::Index t = 0; t < rows; ++t)
    rhs[t] = targets[static_cast<std::size_t>(t)].illuminance -
             photometric(rest.total.row(targets[static_cast<std::size_t>(t)].patch).cast<double>());

  // T: Legendre weights of each hat function (breakpoints at the control angles)
  const double step = pi / intervals;
  std::vector<double> breakpoints;
  for (int k = 0; k <= intervals; ++k) breakpoints.push_back(k * step);
  Eigen::MatrixXd T(degree + 1, intervals + 1);
  for (int k = 0; k <= intervals; ++k) {
    const auto hat = [&](double gamma) {
      return std::max(0.0, 1 - std::abs(gamma - k * step) / step);
    };
    const std::vector<double> w = legendre_weights(hat, degree, breakpoints);
    for (int l = 0; l <= degree; ++l) T(l, k) = w[static_cast<std::size_t>(l)];
  }
  // Z sigma: world SH coefficients of each (smoothed) Legendre degree about the axis
  Eigen::MatrixXd Z(lamp.columns.count, degree + 1);
  for (int l = 0; l <= degree; ++l) {
    std::vector<double> unit(static_cast<std::size_t>(degree + 1), 0.0);
    unit[static_cast<std::size_t>(l)] = sigma ? sigma_factor(degree, l) : 1;
    Z.col(l) = world_coefficients(unit, axis);
  }
  // B: the lamp's basis illuminance at the targets, photometric (Rec. 709 weights of the
  // channels, each with the lamp's colour) and scaled
  const LightSetting& own = lighting[light];
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(rows, lamp.columns.count);
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXf block =
        lamp.total[static_cast<std::size_t>(basis.channels == 1 ? 0 : c)].full();
    const double gain = own.scale * own.colour[static_cast<std::size_t>(c)] * kLuminanceWeights[c];
    for (Eigen::Index t = 0; t < rows; ++t)
      B.row(t) += gain * block.row(targets[static_cast<std::size_t>(t)].patch).cast<double>();
  }
  const Eigen::MatrixXd A = B * Z * T;

  const NnlsResult solved = nonnegative_least_squares(A, rhs);
  DistributionFit fit;
  for (int k = 0; k <= intervals; ++k) {
    fit.angles_deg.push_back(k * 180.0 / intervals);
    fit.candela.push_back(solved.x[k]);
  }
  const Eigen::VectorXd w = T * solved.x;
  fit.weights.assign(w.data(), w.data() + w.size());
  fit.setting = lighting[light];
  fit.setting.coefficients = Z * w;
  const Eigen::VectorXd achieved = A * solved.x - rhs;  // residual
  for (Eigen::Index t = 0; t < rows; ++t) {
    const double residual = achieved[t];
    fit.achieved.push_back(targets[static_cast<std::size_t>(t)].illuminance + residual);
    fit.rms_residual += residual * residual;
    fit.max_residual = std::max(fit.max_residual, std::abs(residual));
  }
  fit.rms_residual = std::sqrt(fit.rms_residual / static_cast<double>(rows));
  return fit;
}

}  // namespace penumbra::basis
