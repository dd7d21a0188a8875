#pragma once
// Rotation of real spherical-harmonic coefficient vectors: re-aiming a lamp whose
// distribution is given in SH (Dobashi 1995 section 3.2). A zonal (rotationally
// symmetric) lamp needs only zonal_sh_coefficients() (spherical_harmonics.h); this is
// for general, asymmetric distributions and for composing aimings.
//
// Method: Galerkin projection by an exact quadrature. Rotating a function,
// g(d) = f(R^T d), maps each band l onto itself, with matrix
//   D^l_{m m'} = integral over the sphere of Y_lm(d) Y_lm'(R^T d).
// Y_lm'(R^T d) is again a polynomial of degree l in d, so the integrand is a polynomial
// of degree 2l and product_sphere_quadrature(2N) integrates every band exactly; the
// only error is round-off. We prefer this to the Ivanic-Ruedenberg recurrences, whose
// published form depends on sign conventions (and had an erratum), and to a
// least-squares fit on sample directions, which needs a well-conditioned point set:
// the projection needs nothing but the basis itself, is orthogonal to round-off, costs
// O(N^5) flops once per aiming (~2e5 for N = 8: 0.2 ms measured), and works for improper
// orthogonal matrices (det -1) too, such as the left-handed photometric C-gamma frame.

#include <Eigen/Core>
#include <vector>

namespace penumbra::basis {

class ShRotation {
 public:
  // computes the band matrices of degree 0..degree for the orthogonal matrix rotation,
  // which maps a lamp's own frame into the world: the rotated lamp sends toward world
  // direction d what the unrotated one sends toward rotation^T d. Preconditions:
  // degree >= 0; rotation orthogonal (|R^T R - I| < 1e-9, else std::invalid_argument).
  ShRotation(int degree, const Eigen::Matrix3d& rotation);

  int degree() const { return static_cast<int>(bands_.size()) - 1; }
  // returns D^l, (2l + 1) x (2l + 1), indexed by m + l.
  const Eigen::MatrixXd& band(int l) const { return bands_.at(l); }
  // returns the block-diagonal (N + 1)^2 square matrix of all bands.
  Eigen::MatrixXd matrix() const;

  // returns the coefficients of the rotated function. Precondition: coefficients has
  // (N' + 1)^2 entries with N' <= degree().
  Eigen::VectorXd apply(const Eigen::VectorXd& coefficients) const;

 private:
  std::vector<Eigen::MatrixXd> bands_;
};

// returns the coefficients of f rotated by rotation, one shot (see ShRotation).
Eigen::VectorXd rotate_sh(const Eigen::VectorXd& coefficients, const Eigen::Matrix3d& rotation);

// returns the rotation taking the z axis to axis (any length > 0) by the shortest arc
// (about z x axis); for axis = -z, the half turn about x.
Eigen::Matrix3d rotation_taking_z_to(const Eigen::Vector3d& axis);

}  // namespace penumbra::basis
