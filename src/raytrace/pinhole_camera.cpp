#include "penumbra/raytrace/pinhole_camera.h"

#include <cmath>

#include "penumbra/scene/scene.h"
#include "vector3.h"

namespace penumbra::raytrace {

PinholeCamera::PinholeCamera(const Camera& camera)
    : eye_(camera.eye), width_(camera.width), height_(camera.height) {
  forward_ = normalized(camera.target - camera.eye);
  right_ = normalized(cross(forward_, camera.up));
  up_ = cross(right_, forward_);
  half_height_ = std::tan(camera.fov_deg * (M_PI / 180) / 2);
  half_width_ = half_height_ * width_ / height_;
}

Vec3d PinholeCamera::direction(double x, double y) const {
  const double across = (2 * x / width_ - 1) * half_width_;
  const double down = (1 - 2 * y / height_) * half_height_;
  return normalized(forward_ + across * right_ + down * up_);
}

std::optional<std::array<double, 3>> PinholeCamera::project(const Vec3d& p) const {
  const Vec3 offset = p - eye_;
  const double depth = dot(offset, forward_);
  if (depth <= 0) return std::nullopt;
  const double x = (dot(offset, right_) / depth / half_width_ + 1) * width_ / 2;
  const double y = (1 - dot(offset, up_) / depth / half_height_) * height_ / 2;
  return std::array<double, 3>{x, y, depth};
}

}  // namespace penumbra::raytrace
