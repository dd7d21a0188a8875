#pragma once
// Real spherical harmonics: Dobashi 1995 section 3.2, eqs. (4)-(10), and its Appendix
// (eqs. 22-23), whose scanned normalisation is wrong for m != 0 (docs/basis.md). This
// basis is orthonormal over the unit sphere and satisfies the addition theorem
//   sum_{m=-l}^{l} Y_lm(a) Y_lm(b) = (2l + 1) / (4 pi) P_l(a . b)    (eq. 7).
//
// Convention (no Condon-Shortley phase), with z = cos theta and phi the azimuth from x:
//   Y_l0      = K_l0 P_l(z)
//   Y_lm      = sqrt(2) K_lm P_l^m(z) cos(m phi)     m > 0
//   Y_l,-m    = sqrt(2) K_lm P_l^m(z) sin(m phi)     m > 0
//   K_lm      = sqrt((2l + 1) / (4 pi) (l - m)! / (l + m)!),
//   P_l^m(z)  = (1 - z^2)^(m/2) d^m/dz^m P_l(z)   (positive for m = l, 0 < z < 1).
// So Y_00 = 1 / sqrt(4 pi) and (Y_1,-1, Y_10, Y_11) = sqrt(3 / (4 pi)) (y, z, x).
// Coefficients up to degree N are stored in one vector of (N + 1)^2 entries,
// Y_lm at index l (l + 1) + m.

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace penumbra::basis {

// returns (degree + 1)^2, the number of real harmonics of degree <= degree.
inline int sh_count(int degree) {
  return (degree + 1) * (degree + 1);
}
// returns the index of Y_lm in a coefficient vector. Precondition: |m| <= l.
inline int sh_index(int l, int m) {
  return l * (l + 1) + m;
}
// returns the degree N of a coefficient vector of (N + 1)^2 entries, or -1 if the
// size is not a square.
int sh_degree(Eigen::Index coefficient_count);

// evaluates Y_lm for all l <= degree, |m| <= l, at direction (any length > 0; only the
// direction matters). Uses the normalised associated-Legendre recurrences in z and
// Re / Im (x + i y)^m for sin^m(theta) cos / sin(m phi), so no angle is formed.
Eigen::VectorXd real_spherical_harmonics(int degree, const Eigen::Vector3d& direction);

// evaluates sum_lm coefficients[lm] Y_lm(direction).
double evaluate_sh(const Eigen::VectorXd& coefficients, const Eigen::Vector3d& direction);

// returns the SH coefficients of the rotationally symmetric distribution
// I(r) = sum_l w_l P_l(axis . r) (Dobashi eqs. 4, 8-10):
//   c_lm = 4 pi / (2l + 1) w_l Y_lm(axis) = A_lm w_l in the paper's eq. (10)
//        = sqrt(4 pi / (2l + 1)) z_l Y_lm(axis), with z_l = sqrt(4 pi / (2l + 1)) w_l the
//          coefficient of the zonal harmonic Y_l0 about the axis.
// legendre_weights are w_0 .. w_N; axis any length > 0.
Eigen::VectorXd zonal_sh_coefficients(const std::vector<double>& legendre_weights,
                                      const Eigen::Vector3d& axis);

// A quadrature rule over the unit sphere: sum_i weights[i] f(directions[i]).
struct SphereQuadrature {
  std::vector<Eigen::Vector3d> directions;
  std::vector<double> weights;
};

// returns the product rule exact for every polynomial of degree <= degree in
// (x, y, z) restricted to the sphere: Gauss-Legendre in z = cos theta with
// degree / 2 + 1 nodes times degree + 1 equally spaced azimuths. (A term
// sin^|m| theta e^{i m phi} q(z) with 0 < |m| <= degree integrates to zero and so does
// its azimuth sum; for m = 0 q has degree <= degree < 2 (degree / 2 + 1).)
// The products Y_lm Y_l'm' with l, l' <= N need degree = 2N.
SphereQuadrature product_sphere_quadrature(int degree);

// returns the coefficients of the L2 projection of function onto the harmonics of
// degree <= degree, c_lm = integral of f Y_lm over the sphere, by quadrature.
Eigen::VectorXd project_sh(const std::function<double(const Eigen::Vector3d&)>& function,
                           int degree, const SphereQuadrature& quadrature);

}  // namespace penumbra::basis
