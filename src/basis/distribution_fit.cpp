#include "penumbra/basis/distribution_fit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/spherical_harmonics.h"
#include "penumbra/photometry/analytic_distribution.h"
#include "penumbra/photometry/table_distribution.h"

namespace penumbra::basis {
namespace {

using photometry::Distribution;

std::vector<double> uniform(double end, int intervals) {
  std::vector<double> nodes;
  for (int i = 0; i <= intervals; ++i) nodes.push_back(end * i / intervals);
  return nodes;
}

std::vector<double> sorted_unique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// Integrates over the sphere piecewise: Gauss-Legendre in gamma between gamma
// breakpoints and, unless the integrand is rotationally symmetric, in C between C
// breakpoints. visit(gamma, c, weight) receives solid-angle weights summing to 4 pi.
// The rule on an interval of length h has enough points for the oscillation of degree
// `degree` over it (2 degree + 24 on the whole half circle, as legendre_weights()).
int points_for(double h, int degree) {
  return std::min(2 * degree + 24, 6 + static_cast<int>(std::ceil(2 * (degree + 1) * h)));
}

template <class Visit>
void integrate_sphere(const DistributionBreakpoints& breakpoints, bool symmetric, int degree,
                      Visit&& visit) {
  std::vector<QuadratureRule> rules(2 * degree + 25);
  const auto rule_on = [&rules, degree](double low, double high) {
    const int points = points_for(high - low, degree);
    if (rules[points].nodes.empty()) rules[points] = gauss_legendre(points);
    return mapped(rules[points], low, high);
  };
  for (std::size_t i = 0; i + 1 < breakpoints.gamma.size(); ++i) {
    const double low = breakpoints.gamma[i], high = breakpoints.gamma[i + 1];
    const QuadratureRule g = rule_on(low, high);
    for (std::size_t a = 0; a < g.nodes.size(); ++a) {
      const double sine_weight = g.weights[a] * std::sin(g.nodes[a]);
      if (symmetric) {
        visit(g.nodes[a], 0.0, 2 * pi * sine_weight);
        continue;
      }
      for (std::size_t j = 0; j + 1 < breakpoints.c.size(); ++j) {
        const double from = breakpoints.c[j], to = breakpoints.c[j + 1];
        const QuadratureRule c = rule_on(from, to);
        for (std::size_t b = 0; b < c.nodes.size(); ++b)
          visit(g.nodes[a], c.nodes[b], sine_weight * c.weights[b]);
      }
    }
  }
}

}  // namespace

bool is_rotationally_symmetric(const Distribution& distribution) {
  return distribution.symmetry() == photometry::Symmetry::axial ||
         distribution.symmetry() == photometry::Symmetry::isotropic;
}

DistributionBreakpoints breakpoints_of(const Distribution& distribution) {
  DistributionBreakpoints breakpoints;
  if (const auto* table = dynamic_cast<const photometry::TableDistribution*>(&distribution);
      table && table->grid().type == photometry::PhotometricType::c) {
    for (double v : table->grid().vertical_deg) breakpoints.gamma.push_back(photometry::radians(v));
    // Every mirror image of a stored C angle: a superset of the unfolded grid's angles
    // for each LM-63 symmetry.
    std::vector<double> c_deg{0, 360};
    for (double h : table->grid().horizontal_deg)
      for (double image : {h, -h, 180 - h, 180 + h}) {
        const double folded = std::fmod(std::fmod(image, 360) + 360, 360);
        c_deg.push_back(folded);
      }
    for (double c : sorted_unique(c_deg)) breakpoints.c.push_back(photometry::radians(c));
    breakpoints.c_exact = true;
  } else if (const auto* spot =
                 dynamic_cast<const photometry::CosPowerDistribution*>(&distribution)) {
    breakpoints.gamma = {spot->spread()};
    breakpoints.c = {0, 2 * pi};
    breakpoints.c_exact = true;
  } else if (dynamic_cast<const photometry::CardioidDistribution*>(&distribution) ||
             distribution.symmetry() == photometry::Symmetry::isotropic) {
    breakpoints.c = {0, 2 * pi};
    breakpoints.c_exact = true;
  } else {
    breakpoints.gamma = uniform(pi, 36);
    breakpoints.c = uniform(2 * pi, 360);
  }
  breakpoints.gamma = normalised_breakpoints(std::move(breakpoints.gamma));
  if (is_rotationally_symmetric(distribution)) {
    breakpoints.c = {0, 2 * pi};
    breakpoints.c_exact = true;
  }
  return breakpoints;
}

AxialProfile axial_profile(const Distribution& distribution,
                           const DistributionBreakpoints& breakpoints) {
  if (is_rotationally_symmetric(distribution))
    return [&distribution](double gamma) { return distribution.intensity(gamma, 0); };
  const std::vector<double> c = breakpoints.c;
  return [&distribution, c](double gamma) {
    // The trapezoid rule over the C breakpoints, exact for a linear-in-C interpolant.
    double sum = 0;
    for (std::size_t j = 0; j + 1 < c.size(); ++j)
      sum += 0.5 * (c[j + 1] - c[j]) *
             (distribution.intensity(gamma, c[j]) + distribution.intensity(gamma, c[j + 1]));
    return sum / (2 * pi);
  };
}

ApproximationError approximation_error(
    const Distribution& distribution,
    const std::function<double(double gamma, double c)>& approximation,
    const DistributionBreakpoints& breakpoints, int degree) {
  const bool symmetric = is_rotationally_symmetric(distribution);
  ApproximationError error;
  error.max_intensity_cd = distribution.max_intensity();

  // The maximum: samples in every gamma interval, both ends nudged inside so that a
  // jump at a breakpoint is seen from both sides.
  std::vector<double> c_samples{0};
  if (!symmetric) {
    c_samples.clear();
    for (std::size_t j = 0; j + 1 < breakpoints.c.size(); ++j) {
      c_samples.push_back(breakpoints.c[j]);
      c_samples.push_back(0.5 * (breakpoints.c[j] + breakpoints.c[j + 1]));
    }
  }
  const double density = 4.0 * (degree + 1);  // samples per radian
  for (std::size_t i = 0; i + 1 < breakpoints.gamma.size(); ++i) {
    const double low = breakpoints.gamma[i], high = breakpoints.gamma[i + 1];
    const double nudge = 1e-9 * (high - low);
    const int count = std::max(8, static_cast<int>(std::ceil(density * (high - low))));
    for (int k = 0; k <= count; ++k) {
      // Reported at the breakpoint itself, evaluated just inside the interval.
      const double reported = low + (high - low) * k / count;
      double gamma = reported;
      if (k == 0) gamma += nudge;
      if (k == count) gamma -= nudge;
      for (double c : c_samples) {
        const double difference =
            std::abs(distribution.intensity(gamma, c) - approximation(gamma, c));
        if (difference > error.max_cd) {
          error.max_cd = difference;
          error.max_gamma = reported;
          error.max_c = c;
        }
      }
    }
  }

  // The RMS over the sphere.
  double sum = 0;
  integrate_sphere(breakpoints, symmetric, degree, [&](double gamma, double c, double weight) {
    const double difference = distribution.intensity(gamma, c) - approximation(gamma, c);
    sum += weight * difference * difference;
  });
  error.rms_cd = std::sqrt(std::max(0.0, sum) / (4 * pi));
  return error;
}

LegendreFit fit_legendre(const Distribution& distribution, int degree, bool use_sigma) {
  if (degree < 0) throw std::invalid_argument("fit_legendre: negative degree");
  const DistributionBreakpoints breakpoints = breakpoints_of(distribution);
  LegendreFit fit;
  fit.azimuthal_average = !is_rotationally_symmetric(distribution);
  // Dobashi eq. (3), piecewise between the distribution's breakpoints.
  fit.series = LegendreSeries(
      legendre_weights(axial_profile(distribution, breakpoints), degree, breakpoints.gamma));
  const LegendreSeries& plain = fit.series;
  fit.error_without_sigma = approximation_error(
      distribution, [&plain](double gamma, double) { return plain(gamma); }, breakpoints, degree);
  fit.sigma = use_sigma;
  if (use_sigma) {
    const LegendreSeries smoothed = fit.series.sigma_smoothed();
    fit.error = approximation_error(
        distribution, [&smoothed](double gamma, double) { return smoothed(gamma); }, breakpoints,
        degree);
  } else {
    fit.error = fit.error_without_sigma;
  }
  return fit;
}

Eigen::VectorXd sh_coefficients_of(const Distribution& distribution, int degree) {
  if (degree < 0) throw std::invalid_argument("sh_coefficients_of: negative degree");
  const DistributionBreakpoints breakpoints = breakpoints_of(distribution);
  if (is_rotationally_symmetric(distribution))
    return zonal_sh_coefficients(
        legendre_weights(axial_profile(distribution, breakpoints), degree, breakpoints.gamma),
        Eigen::Vector3d::UnitZ());
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(sh_count(degree));
  // c_lm = int I Y_lm dOmega; inside each C interval the integrand is smooth.
  integrate_sphere(breakpoints, false, degree, [&](double gamma, double c, double weight) {
    const Eigen::Vector3d direction(std::sin(gamma) * std::cos(c), std::sin(gamma) * std::sin(c),
                                    std::cos(gamma));
    coefficients +=
        (weight * distribution.intensity(gamma, c)) * real_spherical_harmonics(degree, direction);
  });
  return coefficients;
}

Eigen::Matrix3d photometric_frame(const Eigen::Vector3d& axis, const Eigen::Vector3d& c0) {
  Eigen::Matrix3d frame;
  frame.col(0) = c0;
  frame.col(1) = c0.cross(axis);
  frame.col(2) = axis;
  return frame;
}

}  // namespace penumbra::basis
