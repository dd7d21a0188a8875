#include "penumbra/basis/radiosity.h"

#include "penumbra/base/parallel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra::basis {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

RadiosityResult solve_radiosity(const FormFactorMatrix& F, const Eigen::VectorXd& reflectance,
                                const Eigen::MatrixXd& direct, const RadiosityOptions& options) {
  const Eigen::Index n = direct.rows();
  if (F.rows() != n || F.cols() != n || reflectance.size() != n)
    throw std::invalid_argument("radiosity: sizes of F, reflectance and E_direct differ");
  if (n > 0 && (reflectance.minCoeff() < 0 || reflectance.maxCoeff() >= 1))
    throw std::invalid_argument("radiosity: reflectances must lie in [0, 1)");
  const Eigen::Index columns = direct.cols();
  const RowMatrix emission = direct;
  RowMatrix current = emission, next(n, columns), exitance(n, columns);

  RadiosityResult result;
  // the largest |E| per column, for the relative stopping test
  const auto column_scale = [&](const RowMatrix& values) {
    Eigen::RowVectorXd scale = values.cwiseAbs().colwise().maxCoeff();
    for (Eigen::Index c = 0; c < columns; ++c)
      if (scale[c] == 0) scale[c] = 1;
    return scale;
  };
  const auto sweep = [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index i = begin; i < end; ++i) {
      auto row = next.row(i);
      row = emission.row(i);
      for (FormFactorMatrix::InnerIterator entry(F, i); entry; ++entry)
        row.noalias() += entry.value() * exitance.row(entry.col());
    }
  };
  for (result.iterations = 0; result.iterations < options.max_iterations;) {
    exitance = reflectance.asDiagonal() * current;  // B_j = rho_j E_j
    for_each_range(
        static_cast<std::size_t>(n), options.parallel,
        [&](std::size_t begin, std::size_t end) {
          sweep(static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(end));
        },
        64);
    ++result.iterations;
    const Eigen::RowVectorXd change = (next - current).cwiseAbs().colwise().maxCoeff();
    result.last_change = n == 0 ? 0 : (change.array() / column_scale(next).array()).maxCoeff();
    current.swap(next);
    if (result.last_change <= options.tolerance) {
      result.converged = true;
      break;
    }
  }
  result.illuminance = current;
  return result;
}

}  // namespace penumbra::basis
