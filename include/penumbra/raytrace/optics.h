#pragma once
// Ray optics of Whitted 1980 section 2 as pure functions: the sign conventions at a
// surface, the reflected direction R and the transmitted direction P (the paper's V', R, P
// and k_f), total internal reflection, and the dielectric Fresnel reflectance that
// `--fresnel` uses in place of the constant k_s, k_t. See docs/raytrace.md.
//
// Directions are double triples; V is the direction the ray travels (toward the surface).

#include <array>
#include <optional>
#include "penumbra/base/vec3d.h"

namespace penumbra {

// The same alias as in geometry/kernel.h, restated to keep CGAL out of magnitude code.

namespace raytrace {

// The surface as the ray meets it (Whitted section 2: "the intersection processor must
// adjust the sign of N so that it points to the side of the surface from which the
// intersecting ray is incident. It must likewise adjust the index of refraction").
struct FacingSurface {
  Vec3d normal;           // unit normal on the side the ray comes from: V . normal < 0
  double relative_index;  // k_n = n(entered medium) / n(medium left)
  bool entering;          // true when the ray arrives from the outside of the surface
};

// returns the normal flipped to face the ray and the relative index of refraction: ior when
// the ray enters (V . outward < 0), 1 / ior when it leaves. The medium outside every object
// is taken as air (index 1); nested media are not tracked.
//   @param[in] direction  V, the ray's direction (any length > 0)
//   @param[in] outward    unit outward normal of the surface
//   @param[in] ior        index of refraction of the object's material (> 0)
FacingSurface face_the_ray(const Vec3d& direction, const Vec3d& outward, double ior);

// The paper's construction, vectors unnormalised exactly as in section 2:
//   V' = V / |V . N|,  R = V' + 2N,  P = k_f (N + V') - N,
//   k_f = (k_n^2 |V'|^2 - |V' + N|^2)^(-1/2).
struct WhittedVectors {
  Vec3d scaled_incident;           // V'
  Vec3d reflected;                 // R
  std::optional<Vec3d> refracted;  // P; empty under total internal reflection
  double k_f = 0;                  // the refraction factor (0 under total internal reflection)
};

// computes V', R, P and k_f. Precondition: normal is unit and V . normal < 0 (apply
// face_the_ray first); relative_index is k_n of the facing surface.
WhittedVectors whitted_vectors(const Vec3d& direction, const Vec3d& normal, double relative_index);

// returns the unit mirror direction R / |R| (angle of reflection = angle of incidence).
// Precondition: as for whitted_vectors.
Vec3d reflected_direction(const Vec3d& direction, const Vec3d& normal);

// returns the unit transmitted direction P / |P| by Snell's law, or {} under total internal
// reflection (the denominator of k_f imaginary: T is then zero, section 2). Precondition: as
// for whitted_vectors.
std::optional<Vec3d> refracted_direction(const Vec3d& direction, const Vec3d& normal,
                                         double relative_index);

// returns the reflectance of a smooth dielectric interface for unpolarised light, the mean of
// the s and p Fresnel reflectances: 1 under total internal reflection.
//   @param[in] cos_incidence   cosine of the angle of incidence, in [0, 1]
//   @param[in] relative_index  k_n = n(entered medium) / n(medium left)
double fresnel_reflectance(double cos_incidence, double relative_index);

}  // namespace raytrace
}  // namespace penumbra
