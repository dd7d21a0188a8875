#include "penumbra/raytrace/pinhole_camera.h"

#include "vector3.h"

namespace penumbra::raytrace {

Vec3d PinholeCamera::direction(double x, double y) const {
  return normalized(frame_.direction(x, y));
}

}  // namespace penumbra::raytrace
