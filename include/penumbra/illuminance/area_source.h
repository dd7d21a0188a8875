#pragma once
// Illuminance from a Lambertian polygon (area) source: Lambert's closed form, a sum over the
// polygon's edges (docs/area-sources.md derives it). Doubles only: the polygon given is the
// exact visible part of the source, rounded.
//
// A source of luminance L (cd/m^2) seen from a point P with unit normal N gives
//     E = L * Omega_p,   Omega_p = integral over the visible source of cos(alpha) dw,
// the projected solid angle. By Stokes' theorem Omega_p is a sum over the boundary edges
// V_i -> V_{i+1}: with a_i = V_i - P,
//     Omega_p = 1/2 * sum_i theta_i * N . (a_{i+1} x a_i) / |a_{i+1} x a_i|,
// theta_i the angle between a_i and a_{i+1}, when the boundary turns counter-clockwise seen
// from P (from the emitting side) and the polygon lies wholly on the outer side of the plane
// through P with normal N (the receiving face hides the rest: clip the source first).

#include <cstddef>
#include <vector>

#include "penumbra/base/vec3d.h"

namespace penumbra::illuminance {

// returns Omega_p (sr) of the planar region whose boundary rings (outer rings counter-clockwise
// and holes clockwise, seen from point) are given: a flux-weighted solid angle, pi for a
// half-space-filling source. Precondition: the region lies on the outer side of the plane
// through point with unit normal normal.
double projected_solid_angle(const Vec3d& point, const Vec3d& normal,
                             const std::vector<std::vector<Vec3d>>& rings);

// returns the edge sum of one ring of count vertices (positive when it turns
// counter-clockwise seen from point), with the same precondition.
double projected_solid_angle(const Vec3d& point, const Vec3d& normal, const Vec3d* ring,
                             std::size_t count);

}  // namespace penumbra::illuminance
