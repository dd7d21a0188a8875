#pragma once
// Illuminance from a linear Lambertian source: Nishita 1985 section 4.2 (eqs. (5)-(8),
// Fig. 7) with a closed form for every orientation, which the paper (Case C) only integrates
// numerically. Doubles only; the derivation is in docs/illuminance.md.
//
// Source model (eq. (5)): a segment A -> B of length L whose element dl sends the intensity
// I sin(theta) dl toward a direction at angle theta from the segment, I in cd per metre.
// A point P with unit outward normal N receives
//     E = I * integral over the source of sin(theta) cos(alpha) / r^2 dl,
// taken only over the part of the source strictly on the outer side of the plane through P
// with normal N (Fig. 7, face S3: the face itself hides the rest).
//
// Parameters along the source are fractions u in [0, 1]: Q(u) = A + u (B - A).

#include <array>
#include <optional>
#include <utility>
#include <vector>
#include "penumbra/base/vec3d.h"

namespace penumbra {

// The same alias as in geometry/kernel.h (restated to keep CGAL out of magnitude code).

namespace illuminance {

// A sub-segment of the source as fractions [first, second] along A -> B, 0 <= first <= second
// <= 1.
using SourceInterval = std::pair<double, double>;

// computes the parameter interval of the part of the source A -> B strictly on the outer side
// of the plane through `point` with unit normal `normal` (Fig. 7, S3: a plane crossing the
// source splits it and only the outer part lights the face); returns {} when no part is.
// This is the double-precision version for magnitudes: the crossing parameter is rounded.
// The exact shadow engine decides the same question with exact predicates; where they
// disagree the difference is a sub-segment of rounding length whose contribution vanishes
// (the integrand is 0 on the plane).
std::optional<SourceInterval> outer_side_interval(const Vec3d& point, const Vec3d& normal,
                                                  const Vec3d& a, const Vec3d& b);

// computes the illuminance (lux) at `point` (unit outward `normal`) from the whole linear
// source a -> b with `candela_per_metre` I, by the closed form (exact up to rounding in every
// orientation). Returns 0 when no part of the source is strictly on the outer side, when
// a == b, and when `point` lies on the line of the source (every element then sees P along
// its axis, where a Lambertian tube emits nothing).
double linear_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b,
                          double candela_per_metre);

// computes the illuminance from the `visible` sub-segments of the source only (the parts not
// hidden by occluders, Nishita 1985 section 4.2.3), each intersected with the outer-side
// interval. Precondition: every interval has 0 <= first <= second <= 1 (otherwise throws
// std::invalid_argument); intervals must not overlap (they are summed). Empty intervals
// contribute 0.
double linear_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& a, const Vec3d& b,
                          double candela_per_metre, const std::vector<SourceInterval>& visible);

// Controls of the adaptive quadrature.
struct QuadratureOptions {
  double relative_tolerance = 1e-12;  // stop when the error estimate is below this ...
  double absolute_tolerance = 0;      // ... or below this (lux)
  int max_subintervals = 4000;        // give up refining after this many subintervals
};

// computes the same illuminance as linear_illuminance by adaptive Gauss-Kronrod (7-15)
// quadrature of eq. (5) evaluated directly from the vectors: the paper's numerical method of
// Case C, kept as a second, independent method.
double linear_illuminance_quadrature(const Vec3d& point, const Vec3d& normal, const Vec3d& a,
                                     const Vec3d& b, double candela_per_metre,
                                     const QuadratureOptions& options = {});

// computes the quadrature version over the `visible` sub-segments (same precondition as
// linear_illuminance).
double linear_illuminance_quadrature(const Vec3d& point, const Vec3d& normal, const Vec3d& a,
                                     const Vec3d& b, double candela_per_metre,
                                     const std::vector<SourceInterval>& visible,
                                     const QuadratureOptions& options = {});

}  // namespace illuminance
}  // namespace penumbra
