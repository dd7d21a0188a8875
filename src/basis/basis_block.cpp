#include <Eigen/SVD>
#include <cmath>

#include "penumbra/basis/basis_luminances.h"

namespace penumbra::basis {

BasisBlock BasisBlock::compressed(const Eigen::MatrixXd& values, double max_error) {
  if (max_error <= 0 || values.size() == 0) return BasisBlock(values.cast<float>());
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(values, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const double total = sigma.squaredNorm();
  // the smallest rank r whose dropped singular values carry at most max_error^2 of the
  // squared Frobenius norm (Eckart-Young: the truncated SVD is the best rank-r matrix).
  Eigen::Index rank = sigma.size();
  double dropped = 0;
  while (rank > 1) {
    const double next = dropped + sigma[rank - 1] * sigma[rank - 1];
    if (total == 0 || std::sqrt(next / total) > max_error) break;
    dropped = next;
    --rank;
  }
  if (rank == sigma.size()) return BasisBlock(values.cast<float>());
  const Eigen::MatrixXd left = svd.matrixU().leftCols(rank) * sigma.head(rank).asDiagonal();
  return low_rank(left.cast<float>(), svd.matrixV().leftCols(rank).cast<float>(),
                  total == 0 ? 0 : std::sqrt(dropped / total));
}

BasisBlock BasisBlock::low_rank(Eigen::MatrixXf left, Eigen::MatrixXf right, double error) {
  BasisBlock block;
  block.compressed_ = true;
  block.left_ = std::move(left);
  block.right_ = std::move(right);
  block.error_ = error;
  return block;
}

void BasisBlock::accumulate(const Eigen::VectorXf& weights, float scale,
                            Eigen::VectorXf& out) const {
  if (compressed_) {
    const Eigen::VectorXf projected = scale * (right_.transpose() * weights);
    out.noalias() += left_ * projected;
  } else {
    out.noalias() += full_ * (scale * weights);
  }
}

Eigen::MatrixXf BasisBlock::full() const {
  return compressed_ ? Eigen::MatrixXf(left_ * right_.transpose()) : full_;
}

}  // namespace penumbra::basis
