// penumbra lid fit FILE|SPEC --degree N [--sigma] [--json]: Legendre weights of a
// luminous intensity distribution (Dobashi 1995 eq. 3), its sigma factors (eq. 13) and
// the approximation error over the sphere. docs/basis.md.

#include "lid_fit.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "penumbra/base/input_error.h"
#include "penumbra/basis/distribution_fit.h"
#include "penumbra/basis/sigma_factors.h"
#include "penumbra/basis/spherical_harmonics.h"

namespace penumbra::cli {
namespace {

nlohmann::json error_json(const basis::ApproximationError& error) {
  return {{"max_cd", error.max_cd},
          {"max_relative", error.max_relative()},
          {"max_gamma_deg", photometry::degrees(error.max_gamma)},
          {"max_c_deg", photometry::degrees(error.max_c)},
          {"rms_cd", error.rms_cd},
          {"rms_relative", error.rms_relative()}};
}

void print_error(const char* title, const basis::ApproximationError& error, bool asymmetric) {
  std::cout << title << "\n  max " << error.max_cd << " cd (" << 100 * error.max_relative()
            << " % of the max intensity " << error.max_intensity_cd << " cd) at gamma "
            << photometry::degrees(error.max_gamma) << " deg";
  if (asymmetric) std::cout << ", C " << photometry::degrees(error.max_c) << " deg";
  std::cout << "\n  rms " << error.rms_cd << " cd (" << 100 * error.rms_relative() << " %)\n";
}

}  // namespace

int run_lid_fit(const LidFitOptions& options) {
  if (options.degree < 0 || options.degree > kMaxLidFitDegree)
    throw InputError("<command line>", "--degree",
                     "must lie in 0.." + std::to_string(kMaxLidFitDegree));
  const photometry::Distribution& distribution = *options.distribution;
  const basis::LegendreFit fit = basis::fit_legendre(distribution, options.degree, options.sigma);
  const std::vector<double>& weights = fit.series.weights();
  const std::vector<double> sigma = basis::sigma_factors(options.degree);
  // For an asymmetric distribution, what fitting the whole distribution in SH of the
  // same degree ((N + 1)^2 terms, as the radiosity basis needs anyway) would achieve.
  std::optional<basis::ApproximationError> sh_error;
  if (fit.azimuthal_average) {
    const Eigen::VectorXd coefficients = basis::sh_coefficients_of(distribution, options.degree);
    sh_error = basis::approximation_error(
        distribution,
        [&coefficients](double gamma, double c) {
          return basis::evaluate_sh(
              coefficients, Eigen::Vector3d(std::sin(gamma) * std::cos(c),
                                            std::sin(gamma) * std::sin(c), std::cos(gamma)));
        },
        basis::breakpoints_of(distribution), options.degree);
  }

  if (options.json) {
    nlohmann::json out;
    out["degree"] = options.degree;
    out["symmetry"] = photometry::symmetry_name(distribution.symmetry());
    out["fitted"] = fit.azimuthal_average ? "azimuthal_average" : "distribution";
    out["weights"] = weights;
    if (options.sigma) out["sigma"] = sigma;
    out["flux_lm"] = fit.series.flux();
    out["max_intensity_cd"] = distribution.max_intensity();
    out["error"] = error_json(fit.error);
    if (options.sigma) out["error_without_sigma"] = error_json(fit.error_without_sigma);
    if (sh_error) out["sh_fit_error"] = error_json(*sh_error);
    std::cout << out.dump(2) << "\n";
    return 0;
  }

  std::cout << std::setprecision(6);
  if (fit.azimuthal_average)
    std::cout << "the distribution is not rotationally symmetric (symmetry "
              << photometry::symmetry_name(distribution.symmetry())
              << "): the series fits its average over C; the error is against the full "
                 "distribution\n";
  std::cout << "Legendre weights of degree 0.." << options.degree << " (Dobashi eq. 3), candela:\n";
  std::cout << (options.sigma ? "   l  weight          sigma      sigma x weight\n"
                              : "   l  weight\n");
  for (int l = 0; l <= options.degree; ++l) {
    std::cout << std::setw(4) << l << "  " << std::setw(14) << weights[l];
    if (options.sigma)
      std::cout << "  " << std::setw(9) << sigma[l] << "  " << std::setw(14)
                << sigma[l] * weights[l];
    std::cout << "\n";
  }
  std::cout << "flux " << fit.series.flux() << " lm (4 pi w_0)\n";
  print_error(options.sigma ? "error over the sphere, with sigma factors (eq. 12):"
                            : "error over the sphere (eq. 2):",
              fit.error, fit.azimuthal_average);
  if (options.sigma)
    print_error("error without sigma factors:", fit.error_without_sigma, fit.azimuthal_average);
  if (sh_error)
    print_error("for comparison, a spherical-harmonic fit of the whole distribution, same degree:",
                *sh_error, true);
  return 0;
}

}  // namespace penumbra::cli
