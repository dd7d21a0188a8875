#pragma once
// Phong specular term for point and linear sources: Nishita 1985 section 4.2.1 (end), which
// adapts Phong's model, made for point sources, to a linear source by treating the source as
// a series of point sources. See docs/illuminance.md.
//
// These functions return a LUMINANCE (cd/m^2) seen from the viewer, not an illuminance:
// for one point source of intensity I at distance r,
//     L_s = (k_s / pi) * (I / r^2) * cos^n(psi),
// with psi the angle between the viewing direction and the mirror direction of the light
// about the normal, k_s the material's `specular` coefficient and n its `shininess`. The
// factor 1/pi makes k_s = 1, n = 0 the luminance a white Lambertian surface would have under
// the normal illuminance I / r^2. Like Phong's term it has no cos(alpha) factor.
// Tie-breaks: 0 unless the light and the viewer are both strictly on the outer side, and 0
// where cos(psi) <= 0.

#include <array>
#include <vector>

#include "penumbra/illuminance/linear_source.h"

namespace penumbra::illuminance {

// Material constants of Phong's specular term.
struct PhongSpecular {
  double specular = 0;   // k_s, 0..1
  double shininess = 0;  // n >= 0
};

// computes the specular luminance (cd/m^2) at `point` (unit outward `normal`) seen along
// `to_viewer` (unit vector from the point toward the eye) from a point source at `lamp`
// sending `candela` toward the point.
double point_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                      const Vec3d& lamp, double candela, const PhongSpecular& material);

// computes the specular luminance (cd/m^2) from the linear Lambertian source a -> b
// (`candela_per_metre`), the integral of point_specular over its elements of intensity
// I sin(theta) dl, restricted to the outer-side part of the source, by adaptive quadrature.
double linear_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                       const Vec3d& a, const Vec3d& b, double candela_per_metre,
                       const PhongSpecular& material, const QuadratureOptions& options = {});

// computes the same luminance from the `visible` sub-segments only (precondition as for
// linear_illuminance).
double linear_specular(const Vec3d& point, const Vec3d& normal, const Vec3d& to_viewer,
                       const Vec3d& a, const Vec3d& b, double candela_per_metre,
                       const PhongSpecular& material, const std::vector<SourceInterval>& visible,
                       const QuadratureOptions& options = {});

}  // namespace penumbra::illuminance
