#pragma once
// The scene camera (camera.h) as a map between image points and rays, shared by every
// renderer: forward toward target, right = forward x up, up = right x forward, and the
// image plane at distance 1 spanning the vertical field of view. Image coordinates are
// those of DESIGN.md: x in [0, width] to the right, y in [0, height] downward, so pixel
// (i, j) covers [i, i+1] x [j, j+1] and its centre is (i + 0.5, j + 0.5). Doubles only:
// this decides what a pixel shows, never where a shadow lies.

#include <array>
#include <optional>

#include "penumbra/scene/camera.h"

namespace penumbra {

class CameraFrame {
 public:
  // builds the frame. Throws std::invalid_argument when the image has no pixels.
  explicit CameraFrame(const Camera& camera);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3d& eye() const { return eye_; }
  const Vec3d& forward() const { return forward_; }
  const Vec3d& right() const { return right_; }
  const Vec3d& up() const { return up_; }
  // half the image plane's width and height at distance 1.
  double half_width() const { return half_width_; }
  double half_height() const { return half_height_; }

  // returns the direction through image point (x, y), scaled so that its component along
  // forward is 1: eye + t * direction lies at depth t.
  Vec3d direction(double x, double y) const;

  // returns the unit direction of the ray through image point (x, y) (the ray tracer's).
  Vec3d unit_direction(double x, double y) const;

  // the size of one pixel on the image plane at distance 1 (radians near the axis).
  double pixel_angle() const { return 2 * half_height_ / height_; }

  // returns the image point (x, y) where p projects and its depth along forward, or {}
  // when p is not in front of the eye.
  std::optional<std::array<double, 3>> project(const Vec3d& p) const;

  // returns the camera coordinates of p: (right, up, forward) components of p - eye.
  std::array<double, 3> to_camera(const Vec3d& p) const;

 private:
  Vec3d eye_, forward_, right_, up_;
  double half_width_, half_height_;
  int width_, height_;
};

}  // namespace penumbra
