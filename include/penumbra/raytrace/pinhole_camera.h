#pragma once
// The scene's pinhole camera (DESIGN.md, "Scene file": `camera`) as a map from image
// coordinates to rays. Image coordinates are continuous: x in [0, width] to the right,
// y in [0, height] downward, so pixel (i, j) covers [i, i+1] x [j, j+1], its centre is
// (i + 0.5, j + 0.5) and its corners (Whitted section 3, Fig. 5a) are integer points.

#include "penumbra/vec3d.h"
#include <array>
#include <optional>

namespace penumbra {

struct Camera;

namespace raytrace {

class PinholeCamera {
 public:
  // builds the camera frame: forward toward target, right = forward x up, and the image
  // plane at distance 1 spanning the vertical field of view.
  explicit PinholeCamera(const Camera& camera);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3d& eye() const { return eye_; }

  // returns the unit direction of the ray through image point (x, y).
  Vec3d direction(double x, double y) const;

  // returns the image point where world point p projects and its distance in front of the
  // eye along the view axis, or {} when p is not in front of the eye.
  std::optional<std::array<double, 3>> project(const Vec3d& p) const;

  // the size of one pixel on the image plane at distance 1 (radians near the axis).
  double pixel_angle() const { return 2 * half_height_ / height_; }

 private:
  Vec3d eye_, forward_, right_, up_;
  double half_width_, half_height_;
  int width_, height_;
};

}  // namespace raytrace
}  // namespace penumbra
