#include "penumbra/photometry/orientation.h"

#include <algorithm>
#include <cmath>
#include "penumbra/base/numbers.h"

namespace penumbra::photometry {
namespace {

double dot(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

PhotometricDirection photometric_angles(const Vec3d& axis, const Vec3d& c0,
                                        const Vec3d& direction) {
  const Vec3d c90 = cross(c0, axis);
  const double along = dot(direction, axis);
  const double x = dot(direction, c0), y = dot(direction, c90);
  // atan2 of the sideways length and the axial part: accurate near 0 and pi, where
  // acos of a normalised dot product loses half its digits.
  PhotometricDirection angles;
  angles.gamma = std::atan2(std::hypot(x, y), along);
  angles.c = std::atan2(y, x);
  if (angles.c < 0) angles.c += 2 * pi;
  return angles;
}

Vec3d world_direction(const Vec3d& axis, const Vec3d& c0, const PhotometricDirection& angles) {
  const Vec3d c90 = cross(c0, axis);
  const double s = std::sin(angles.gamma), a = std::cos(angles.gamma);
  const double x = s * std::cos(angles.c), y = s * std::sin(angles.c);
  return {a * axis[0] + x * c0[0] + y * c90[0], a * axis[1] + x * c0[1] + y * c90[1],
          a * axis[2] + x * c0[2] + y * c90[2]};
}

double intensity_toward(const Distribution& distribution, const Vec3d& axis, const Vec3d& c0,
                        const Vec3d& direction) {
  const PhotometricDirection angles = photometric_angles(axis, c0, direction);
  return distribution.intensity(angles.gamma, angles.c);
}

}  // namespace penumbra::photometry
