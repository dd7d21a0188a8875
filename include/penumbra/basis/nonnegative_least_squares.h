#pragma once
// Non-negative least squares: min |A x - b| subject to x >= 0, by the active-set method of
// Lawson and Hanson (Solving Least Squares Problems, 1974, chapter 23, algorithm NNLS).
// For the inverse lighting problem (relight --fit), where the unknowns are intensities.

#include <Eigen/Core>

namespace penumbra::basis {

struct NnlsResult {
  Eigen::VectorXd x;
  int iterations = 0;
  bool converged = false;
};

// solves min |A x - b|, x >= 0. tolerance bounds the gradient of the free set's
// complement (relative to |A^T b|) below which the optimum is accepted.
NnlsResult nonnegative_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                     double tolerance = 1e-12, int max_iterations = 0);

}  // namespace penumbra::basis
