#pragma once
// Legendre series and spherical harmonics of the photometry layer's distributions
// (Dobashi 1995 sections 3.1-3.3), with the approximation error over the sphere.
//
// A Legendre series (a function of gamma alone) represents a rotationally symmetric
// distribution. For an asymmetric (C-gamma) one, fit_legendre() fits its azimuthal
// average (1 / 2 pi) int I(gamma, C) dC, the L2-nearest rotationally symmetric function,
// and measures the error against the full distribution, asymmetry included;
// sh_coefficients_of() represents the whole distribution in SH instead.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "penumbra/basis/legendre_series.h"
#include "penumbra/photometry/distribution.h"

namespace penumbra::basis {

// Angles (radians) between which a distribution's interpolant is smooth.
struct DistributionBreakpoints {
  std::vector<double> gamma;  // sorted, within [0, pi], 0 and pi included
  std::vector<double> c;      // sorted, within [0, 2 pi], 0 and 2 pi included
  // whether c lists every kink of the (piecewise-linear in C) interpolant, so that the
  // trapezoid rule over c is exact; otherwise c is a uniform grid.
  bool c_exact = false;
};

// returns the breakpoints a distribution exposes: a type C table's gamma angles and its
// C angles with their mirror images (a superset of the kinks whatever the symmetry),
// a spot's spread angle (photometry/analytic_distribution.h). Distributions that expose
// nothing get 36 equal gamma intervals and 360 equal C intervals.
DistributionBreakpoints breakpoints_of(const photometry::Distribution& distribution);

// returns whether the distribution is the same in every C plane (axial or isotropic).
bool is_rotationally_symmetric(const photometry::Distribution& distribution);

// returns I(gamma, 0) for a rotationally symmetric distribution, else the azimuthal
// average over C (trapezoid over breakpoints.c: exact for a table's linear-in-C
// interpolation). The distribution must outlive the profile.
AxialProfile axial_profile(const photometry::Distribution& distribution,
                           const DistributionBreakpoints& breakpoints);

// An approximation's error against the distribution over the whole sphere.
struct ApproximationError {
  double max_cd = 0;            // max |I - approximation| over the sampled directions
  double max_gamma = 0;         // where it is largest, radians
  double max_c = 0;             //
  double rms_cd = 0;            // sqrt((1 / 4 pi) int (I - approximation)^2 dOmega)
  double max_intensity_cd = 0;  // the distribution's max_intensity()

  // returns max_cd / max_intensity_cd (0 for a dark distribution).
  double max_relative() const { return max_intensity_cd > 0 ? max_cd / max_intensity_cd : 0; }
  // returns rms_cd / max_intensity_cd.
  double rms_relative() const { return max_intensity_cd > 0 ? rms_cd / max_intensity_cd : 0; }
};

// measures approximation(gamma, c) against the distribution. The maximum is taken over
// samples that include both sides of every breakpoint (so a jump counts in full) and
// at least 4 (degree + 1) samples per radian; the RMS integrates piecewise by
// Gauss-Legendre between breakpoints (in C too, for an asymmetric distribution).
ApproximationError approximation_error(
    const photometry::Distribution& distribution,
    const std::function<double(double gamma, double c)>& approximation,
    const DistributionBreakpoints& breakpoints, int degree);

// The Legendre fit of a distribution, as `penumbra lid fit` prints it.
struct LegendreFit {
  LegendreSeries series;           // the weights of eq. (3), without sigma factors
  bool azimuthal_average = false;  // the distribution was asymmetric: its average was fitted
  bool sigma = false;              // whether `error` is that of the sigma-smoothed series
  ApproximationError error;        // of the series used (eq. 12 when sigma, else eq. 2)
  ApproximationError error_without_sigma;  // of eq. (2), always
};

// fits the Legendre series of degree (>= 0) to distribution (eq. 3 by piecewise
// Gauss-Legendre) and measures its error, with sigma factors (eq. 12) when use_sigma.
LegendreFit fit_legendre(const photometry::Distribution& distribution, int degree, bool use_sigma);

// returns the SH coefficients (spherical_harmonics.h) of degree <= degree of the
// distribution in its photometric frame: x toward C = 0, y toward C = 90, z the axis,
// direction (sin g cos C, sin g sin C, cos g). Rotationally symmetric distributions go
// through their Legendre weights (eq. 10); others by piecewise Gauss-Legendre
// quadrature in gamma and C.
Eigen::VectorXd sh_coefficients_of(const photometry::Distribution& distribution, int degree);

// returns the orthogonal matrix whose columns are the world directions of the
// photometric frame's x (C = 0: c0), y (C = 90: c0 x axis, photometry/orientation.h) and
// z (axis). Its determinant is -1: C grows clockwise about the axis. ShRotation accepts
// it, and maps photometric-frame coefficients into the world. Preconditions: axis and
// c0 unit and orthogonal.
Eigen::Matrix3d photometric_frame(const Eigen::Vector3d& axis, const Eigen::Vector3d& c0);

}  // namespace penumbra::basis
