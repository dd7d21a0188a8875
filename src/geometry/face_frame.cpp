#include "penumbra/geometry/face_frame.h"

#include <cmath>

namespace penumbra {
namespace {

Vec3d unit(const Vector3& v) {
  const Vec3d d = to_double(v);
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / length, d[1] / length, d[2] / length};
}

}  // namespace

Vec3d FaceFrame::unit_u() const {
  return unit(u_);
}
Vec3d FaceFrame::unit_v() const {
  return unit(v_);
}

}  // namespace penumbra
