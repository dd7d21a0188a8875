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

FaceFrame::FaceFrame(const Point3& origin, const Vector3& u_direction, const Vector3& normal)
    : origin_(origin), u_(u_direction) {
  const RationalVector3& u = CGAL::exact(u_direction);
  const RationalVector3 v = CGAL::cross_product(CGAL::exact(normal), u);
  uu_ = u.squared_length();
  vv_ = v.squared_length();
  v_ = from_exact<Vector3>(v);
}

RationalPoint2 FaceFrame::to_frame(const RationalPoint3& p) const {
  const RationalVector3 d = p - CGAL::exact(origin_);
  return {(d * CGAL::exact(u_)) / uu_, (d * CGAL::exact(v_)) / vv_};
}

RationalPoint3 FaceFrame::to_world(const RationalPoint2& q) const {
  return CGAL::exact(origin_) + q.x() * CGAL::exact(u_) + q.y() * CGAL::exact(v_);
}

Point2 FaceFrame::to_frame(const Point3& p) const {
  return from_exact<Point2>(to_frame(CGAL::exact(p)));
}

Point3 FaceFrame::to_world(const Point2& q) const {
  return from_exact<Point3>(to_world(CGAL::exact(q)));
}

Vec3d FaceFrame::unit_u() const {
  return unit(u_);
}
Vec3d FaceFrame::unit_v() const {
  return unit(v_);
}

}  // namespace penumbra
