#include "penumbra/basis/sh_rotation.h"

#include <Eigen/Geometry>
#include <stdexcept>

#include "penumbra/basis/spherical_harmonics.h"

namespace penumbra::basis {

ShRotation::ShRotation(int degree, const Eigen::Matrix3d& rotation) {
  if (degree < 0) throw std::invalid_argument("ShRotation: negative degree");
  if (!((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() < 1e-9))
    throw std::invalid_argument("ShRotation: the matrix is not orthogonal");
  for (int l = 0; l <= degree; ++l) bands_.push_back(Eigen::MatrixXd::Zero(2 * l + 1, 2 * l + 1));
  // D^l_{m m'} = sum_q w_q Y_lm(d_q) Y_lm'(R^T d_q), exact for degree 2N integrands.
  const SphereQuadrature quadrature = product_sphere_quadrature(2 * degree);
  for (std::size_t q = 0; q < quadrature.directions.size(); ++q) {
    const Eigen::Vector3d& d = quadrature.directions[q];
    const Eigen::VectorXd here = real_spherical_harmonics(degree, d);
    const Eigen::VectorXd there = real_spherical_harmonics(degree, rotation.transpose() * d);
    for (int l = 0; l <= degree; ++l) {
      const int first = sh_index(l, -l), size = 2 * l + 1;
      bands_[l].noalias() += quadrature.weights[q] * here.segment(first, size) *
                             there.segment(first, size).transpose();
    }
  }
}

Eigen::MatrixXd ShRotation::matrix() const {
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(sh_count(degree()), sh_count(degree()));
  for (int l = 0; l <= degree(); ++l) {
    const int first = sh_index(l, -l), size = 2 * l + 1;
    full.block(first, first, size, size) = bands_[l];
  }
  return full;
}

Eigen::VectorXd ShRotation::apply(const Eigen::VectorXd& coefficients) const {
  const int degree_in = sh_degree(coefficients.size());
  if (degree_in < 0 || degree_in > degree())
    throw std::invalid_argument("ShRotation::apply: coefficient count is not (N' + 1)^2, N' <= N");
  Eigen::VectorXd rotated(coefficients.size());
  for (int l = 0; l <= degree_in; ++l) {
    const int first = sh_index(l, -l), size = 2 * l + 1;
    rotated.segment(first, size).noalias() = bands_[l] * coefficients.segment(first, size);
  }
  return rotated;
}

Eigen::VectorXd rotate_sh(const Eigen::VectorXd& coefficients, const Eigen::Matrix3d& rotation) {
  const int degree = sh_degree(coefficients.size());
  if (degree < 0) throw std::invalid_argument("rotate_sh: size is not (N + 1)^2");
  return ShRotation(degree, rotation).apply(coefficients);
}

Eigen::Matrix3d rotation_taking_z_to(const Eigen::Vector3d& axis) {
  const double length = axis.norm();
  if (!(length > 0)) throw std::invalid_argument("rotation_taking_z_to: zero axis");
  const Eigen::Vector3d target = axis / length;
  if (target.z() < -1 + 1e-15)
    return Eigen::AngleAxisd(3.14159265358979323846, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), target).toRotationMatrix();
}

}  // namespace penumbra::basis
