#include "penumbra/raytrace/optics.h"

#include <algorithm>
#include <cmath>

#include "penumbra/base/vec3d.h"

namespace penumbra::raytrace {

using namespace vector_ops;

FacingSurface face_the_ray(const Vec3d& direction, const Vec3d& outward, double ior) {
  // Whitted section 2: the formulas for R and P assume V . N < 0.
  if (dot(direction, outward) < 0) return {outward, ior, true};
  return {-outward, 1 / ior, false};
}

WhittedVectors whitted_vectors(const Vec3d& direction, const Vec3d& normal, double relative_index) {
  WhittedVectors out;
  out.scaled_incident = (1 / std::abs(dot(direction, normal))) * direction;
  const Vec3d& v_prime = out.scaled_incident;
  out.reflected = v_prime + 2 * normal;
  // V' . N = -1, so V' + N is the tangential part of V' (length tan(theta_i)) and
  // k_n^2 |V'|^2 - |V' + N|^2 = k_n^2 sec^2 - tan^2, negative exactly when
  // sin(theta_i) > k_n: total internal reflection.
  const Vec3d tangential = v_prime + normal;
  const double radicand =
      relative_index * relative_index * dot(v_prime, v_prime) - dot(tangential, tangential);
  if (radicand <= 0) return out;
  out.k_f = 1 / std::sqrt(radicand);
  out.refracted = out.k_f * tangential - normal;
  return out;
}

Vec3d reflected_direction(const Vec3d& direction, const Vec3d& normal) {
  return normalized(whitted_vectors(direction, normal, 1).reflected);
}

std::optional<Vec3d> refracted_direction(const Vec3d& direction, const Vec3d& normal,
                                         double relative_index) {
  const WhittedVectors vectors = whitted_vectors(direction, normal, relative_index);
  if (!vectors.refracted) return std::nullopt;
  return normalized(*vectors.refracted);
}

double fresnel_reflectance(double cos_incidence, double relative_index) {
  const double cos_i = std::min(1.0, std::abs(cos_incidence));
  const double sin_t2 = (1 - cos_i * cos_i) / (relative_index * relative_index);
  if (sin_t2 >= 1) return 1;
  const double cos_t = std::sqrt(1 - sin_t2);
  // Fresnel's amplitude ratios with n1 = 1, n2 = k_n (only their ratio matters).
  const double r_s = (cos_i - relative_index * cos_t) / (cos_i + relative_index * cos_t);
  const double r_p = (relative_index * cos_i - cos_t) / (relative_index * cos_i + cos_t);
  return (r_s * r_s + r_p * r_p) / 2;
}

}  // namespace penumbra::raytrace
