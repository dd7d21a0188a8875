#include "penumbra/basis/nonnegative_least_squares.h"

#include <Eigen/QR>
#include <limits>
#include <vector>

namespace penumbra::basis {

namespace {

// the least-squares solution on the free columns (others 0), by column-pivoting QR.
Eigen::VectorXd solve_free(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                           const std::vector<bool>& free) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index j = 0; j < A.cols(); ++j)
    if (free[static_cast<std::size_t>(j)]) columns.push_back(j);
  Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k)
    sub.col(static_cast<Eigen::Index>(k)) = A.col(columns[k]);
  const Eigen::VectorXd y = sub.colPivHouseholderQr().solve(b);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(A.cols());
  for (std::size_t k = 0; k < columns.size(); ++k) z[columns[k]] = y[static_cast<Eigen::Index>(k)];
  return z;
}

}  // namespace

NnlsResult nonnegative_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                     double tolerance, int max_iterations) {
  const Eigen::Index n = A.cols();
  if (max_iterations <= 0) max_iterations = static_cast<int>(3 * n + 10);
  NnlsResult result;
  result.x = Eigen::VectorXd::Zero(n);
  std::vector<bool> free(static_cast<std::size_t>(n), false);
  const double scale =
      std::max((A.transpose() * b).cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  for (result.iterations = 0; result.iterations < max_iterations; ++result.iterations) {
    // the negative gradient w = A^T (b - A x); stop when no bound variable would improve
    const Eigen::VectorXd w = A.transpose() * (b - A * result.x);
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!free[static_cast<std::size_t>(j)] && w[j] > tolerance * scale &&
          (best < 0 || w[j] > w[best]))
        best = j;
    if (best < 0) {
      result.converged = true;
      return result;
    }
    free[static_cast<std::size_t>(best)] = true;
    // inner loop: step toward the free least-squares solution until it is feasible
    for (int inner = 0; inner <= n; ++inner) {
      const Eigen::VectorXd z = solve_free(A, b, free);
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j)
        if (free[static_cast<std::size_t>(j)] && z[j] <= 0) feasible = false;
      if (feasible) {
        result.x = z;
        break;
      }
      double alpha = 1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (free[static_cast<std::size_t>(j)] && z[j] <= 0)
          alpha = std::min(alpha, result.x[j] / (result.x[j] - z[j]));
      result.x += alpha * (z - result.x);
      for (Eigen::Index j = 0; j < n; ++j)
        if (free[static_cast<std::size_t>(j)] && result.x[j] <= 0) {
          free[static_cast<std::size_t>(j)] = false;
          result.x[j] = 0;
        }
    }
  }
  return result;
}

}  // namespace penumbra::basis
