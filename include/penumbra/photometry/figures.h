#pragma once
// Figures derived from a distribution (penumbra lid info): flux, maximum intensity,
// beam and field angles, symmetry, and the partial sphere of lighting of Nishita
// 1985 section 3.1, Fig. 2.

#include <array>
#include <optional>

#include "penumbra/photometry/distribution.h"

namespace penumbra::photometry {

struct FigureOptions {
  // Nishita section 3.1: an 8-bit display shows nothing below 1/256 of full scale.
  double threshold = 1.0 / 256;
  // the illuminance shown at full scale, lux: light below threshold * full_scale_lux
  // is insignificant. 500 lx (an office task level) unless the caller says otherwise.
  double full_scale_lux = 500;
};

// Nishita 1985 Fig. 2: the part of a sphere about the source outside which the
// lighting cannot be seen on the display. Directions where the intensity is below
// threshold * max_intensity count as dark; at distance r a direction of intensity I
// gives at most I / r^2, so it matters only within r = sqrt(I / (threshold * E_full)).
struct PartialSphere {
  double threshold = 0;
  double full_scale_lux = 0;
  double spread_deg = 0;      // theta_c: the largest gamma with I >= threshold * I_max
  double radius_m = 0;        // r_a, from the maximum intensity
  bool two_spheres = false;   // Fig. 2b: spread beyond 90 degrees
  double lower_radius_m = 0;  // r_l: gamma <= 90 (the axis side; below a downlight)
  double upper_radius_m = 0;  // r_u: gamma > 90 (0 when spread <= 90)
};

struct Figures {
  double lumens = 0;  // integrated over the sphere
  double max_candela = 0;
  PhotometricDirection max_direction;
  Symmetry symmetry = Symmetry::none;
  // full angles over which I >= 50% (beam) and 10% (field) of max_candela, along the
  // two great circles through the direction of maximum intensity: [0] the one through
  // the axis, [1] the one across it. For a maximum on the axis these are the C0-C180
  // and C90-C270 planes. The single figures are the mean of the two.
  std::array<double, 2> beam_planes_deg{};
  std::array<double, 2> field_planes_deg{};
  double beam_angle_deg = 0;
  double field_angle_deg = 0;
  PartialSphere partial_sphere;
};

// returns the largest gamma (radians) in the half-plane c where the intensity reaches
// level, found on a 0.05 degree scan refined by bisection; nullopt when it never does.
std::optional<double> outermost_gamma(const Distribution& distribution, double c, double level);

// computes the partial sphere of lighting of distribution.
PartialSphere partial_sphere(const Distribution& distribution, const FigureOptions& options = {});

// computes every derived figure of distribution.
Figures compute_figures(const Distribution& distribution, const FigureOptions& options = {});

}  // namespace penumbra::photometry
