#pragma once
// The scene's camera (DESIGN.md, "Scene file": `camera`): a pinhole at eye looking at
// target, with up, a vertical field of view and an image size in pixels. No CGAL here, so
// layers that only draw can include it alone.

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

}  // namespace penumbra
