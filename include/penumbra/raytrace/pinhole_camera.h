#pragma once
// The scene's pinhole camera (DESIGN.md, "Scene file": `camera`) as a map from image
// coordinates to rays: scene/camera_frame.h with unit ray directions. Image coordinates
// are continuous: x in [0, width] to the right, y in [0, height] downward, so pixel (i, j)
// covers [i, i+1] x [j, j+1], its centre is (i + 0.5, j + 0.5) and its corners (Whitted
// section 3, Fig. 5a) are integer points.

#include <array>
#include <optional>

#include "penumbra/scene/camera_frame.h"

namespace penumbra::raytrace {

class PinholeCamera {
 public:
  explicit PinholeCamera(const Camera& camera) : frame_(camera) {}

  int width() const { return frame_.width(); }
  int height() const { return frame_.height(); }
  const Vec3d& eye() const { return frame_.eye(); }

  // returns the unit direction of the ray through image point (x, y).
  Vec3d direction(double x, double y) const;

  // returns the image point where world point p projects and its distance in front of the
  // eye along the view axis, or {} when p is not in front of the eye.
  std::optional<std::array<double, 3>> project(const Vec3d& p) const { return frame_.project(p); }

  // the size of one pixel on the image plane at distance 1 (radians near the axis).
  double pixel_angle() const { return 2 * frame_.half_height() / frame_.height(); }

 private:
  CameraFrame frame_;
};

}  // namespace penumbra::raytrace
