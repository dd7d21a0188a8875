#include "penumbra/illuminance/point_source.h"

#include <cmath>

#include "penumbra/base/vec3d.h"

namespace penumbra::illuminance {

using namespace vector_ops;

namespace detail {

std::pair<double, Vec3d> point_geometry(const Vec3d& point, const Vec3d& normal,
                                        const Vec3d& lamp) {
  const Vec3d to_lamp = lamp - point;
  // Nishita 1985 eq. (3): F(S_f, Q) = N . (Q - P) is the signed distance of the lamp from
  // the face's plane; cos(alpha) = F / r. Not strictly positive: the face does not see it.
  const double signed_distance = dot(normal, to_lamp);
  if (!(signed_distance > 0)) return {0.0, Vec3d{0, 0, 0}};
  const double r = length(to_lamp);
  const double inverse_r = 1 / r;
  // Eq. (4): cos(alpha) / r^2 = F / r^3.
  return {signed_distance * inverse_r * inverse_r * inverse_r, -inverse_r * to_lamp};
}

}  // namespace detail

double point_illuminance(const Vec3d& point, const Vec3d& normal, const Vec3d& lamp,
                         double candela) {
  return candela * detail::point_geometry(point, normal, lamp).first;
}

double directional_illuminance(const Vec3d& normal, const Vec3d& travel_direction,
                               double normal_illuminance) {
  // The light arrives from -travel_direction, so cos(alpha) = -N . travel / |travel|.
  const double cos_alpha = -dot(normal, travel_direction) / length(travel_direction);
  if (!(cos_alpha > 0)) return 0;
  return normal_illuminance * cos_alpha;
}

}  // namespace penumbra::illuminance
