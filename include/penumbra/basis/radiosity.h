#pragma once
// The radiosity system with many right-hand sides (Dobashi 1995 eqs. 14, 16, 17).
//
// In illuminance: a diffuse patch j leaves exitance B_j = rho_j E_j (lm/m^2), and the
// light reaching patch i is its direct illuminance plus what the others send it,
//     E_i = E_direct,i + sum_j F_ij rho_j E_j            (eq. 14 divided by rho_i)
// which is eq. (14) for B_i = rho_i E_i with emission rho_i E_direct,i. Luminance is
// L_i = rho_i E_i / pi. Each column of E_direct is one right-hand side (one basis function
// of one light, eq. 17); all share F and are solved together.
//
// Method: Jacobi iteration E <- E_direct + F (rho . E) from E = E_direct, columns at once,
// rows in parallel. It converges for every rho < 1 because the row sums of F are <= 1: the
// error after k sweeps is at most rho_max^k times the first. It stops when the largest
// change of a sweep is below tolerance times the largest |E| (per column).

#include <Eigen/Core>

#include "penumbra/basis/form_factors.h"

namespace penumbra::basis {

struct RadiosityOptions {
  double tolerance = 1e-6;  // relative change of a sweep at which to stop
  int max_iterations = 10000;
  bool parallel = true;
};

struct RadiosityResult {
  Eigen::MatrixXd illuminance;  // n x columns: E_i per right-hand side (lux)
  int iterations = 0;
  double last_change = 0;  // the last sweep's largest relative change
  bool converged = false;
};

// solves E = E_direct + F diag(reflectance) E for every column of direct.
// Preconditions: F is n x n, reflectance has n entries in [0, 1), direct has n rows.
RadiosityResult solve_radiosity(const FormFactorMatrix& F, const Eigen::VectorXd& reflectance,
                                const Eigen::MatrixXd& direct,
                                const RadiosityOptions& options = {});

}  // namespace penumbra::basis
