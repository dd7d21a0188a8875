#pragma once
// The scene's camera (DESIGN.md, "Scene file": `camera`): a pinhole at eye looking at
// target, with up, a vertical field of view and an image size in pixels. No CGAL here, so
// layers that only draw can include it alone.

#include <string>

#include "penumbra/base/vec3d.h"

namespace penumbra {

struct Camera {
  Vec3d eye{0, 0, 0};
  Vec3d target{0, 0, -1};
  Vec3d up{0, 0, 1};
  double fov_deg = 60;  // vertical field of view
  int width = 640;
  int height = 480;
};

// The largest images penumbra makes (docs/reliability.md, "Limits"): at most 16384 pixels a
// side and 2^26 (67 million, 8192 x 8192) in all, checked before the image is allocated.
inline constexpr int max_image_side = 16384;
inline constexpr long long max_image_pixels = 1LL << 26;

// returns what is wrong with an image of width x height pixels, or "" when it is within the
// limits.
inline std::string image_size_problem(int width, int height) {
  if (width < 1 || height < 1) return "the image size must be positive";
  if (width > max_image_side || height > max_image_side)
    return "an image side is at most " + std::to_string(max_image_side) + " pixels";
  if (static_cast<long long>(width) * height > max_image_pixels)
    return "an image has at most " + std::to_string(max_image_pixels) + " pixels (" +
           std::to_string(width) + " x " + std::to_string(height) + " asked)";
  return "";
}

}  // namespace penumbra
