#include "penumbra/scene/camera_frame.h"

#include <cmath>
#include <stdexcept>
#include "penumbra/base/numbers.h"

namespace penumbra {

using namespace vector_ops;

CameraFrame::CameraFrame(const Camera& camera)
    : eye_(camera.eye), width_(camera.width), height_(camera.height) {
  if (camera.width <= 0 || camera.height <= 0)
    throw std::invalid_argument("camera: the image needs a positive size");
  forward_ = normalized(camera.target - camera.eye);
  right_ = normalized(cross(forward_, camera.up));
  up_ = cross(right_, forward_);
  half_height_ = std::tan(camera.fov_deg * (pi / 180) / 2);
  half_width_ = half_height_ * width_ / height_;
}

Vec3d CameraFrame::direction(double x, double y) const {
  const double across = (2 * x / width_ - 1) * half_width_;
  const double down = (1 - 2 * y / height_) * half_height_;
  return forward_ + across * right_ + down * up_;
}

Vec3d CameraFrame::unit_direction(double x, double y) const {
  return normalized(direction(x, y));
}

std::optional<std::array<double, 3>> CameraFrame::project(const Vec3d& p) const {
  const auto [x_camera, y_camera, depth] = to_camera(p);
  if (depth <= 0) return std::nullopt;
  const double x = (x_camera / depth / half_width_ + 1) * width_ / 2;
  const double y = (1 - y_camera / depth / half_height_) * height_ / 2;
  return std::array<double, 3>{x, y, depth};
}

std::array<double, 3> CameraFrame::to_camera(const Vec3d& p) const {
  const Vec3d offset = p - eye_;
  return {dot(offset, right_), dot(offset, up_), dot(offset, forward_)};
}

}  // namespace penumbra
