#include "penumbra/geometry/face_frame.h"

#include <cmath>

#include "penumbra/geometry/exact.h"

namespace penumbra {
namespace {

Vec3d unit(const Vector3& v) {
  const Vec3d d = to_double(v);
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / length, d[1] / length, d[2] / length};
}

}  // namespace

FaceFrame::FaceFrame(const Point3& origin, const Vector3& u_direction, const Vector3& normal)
    : origin_(origin),
      u_(u_direction),
      v_(CGAL::cross_product(normal, u_direction)),
      uu_(u_.squared_length()),
      vv_(v_.squared_length()) {}

FaceFrame::FaceFrame(const Point3& origin, RationalVector3 u, RationalVector3 v, Rational uu,
                     Rational vv)
    : origin_(origin),
      u_(from_exact<Vector3>(std::move(u))),
      v_(from_exact<Vector3>(std::move(v))),
      uu_(exact_number(std::move(uu))),
      vv_(exact_number(std::move(vv))) {}

RationalPoint2 FaceFrame::to_frame(const RationalPoint3& p) const {
  const RationalVector3 d = p - exact_value(origin_);
  return {(d * exact_value(u_)) / exact_value(uu_), (d * exact_value(v_)) / exact_value(vv_)};
}

RationalPoint3 FaceFrame::to_world(const RationalPoint2& q) const {
  // origin + x u + y v, skipping the zero and unit products of axis-aligned frames (the
  // usual case in CAD): each rational product costs a gcd. The same value.
  const auto add = [](Rational& sum, const Rational& x, const Rational& w) {
    if (CGAL::is_zero(w) || CGAL::is_zero(x)) return;
    if (CGAL::is_one(w))
      sum += x;
    else if (CGAL::is_one(-w))
      sum -= x;
    else
      sum += x * w;
  };
  const RationalPoint3& o = exact_value(origin_);
  const RationalVector3& u = exact_value(u_);
  const RationalVector3& v = exact_value(v_);
  Rational world[3] = {o.x(), o.y(), o.z()};
  for (int i = 0; i < 3; ++i) {
    add(world[i], q.x(), u[i]);
    add(world[i], q.y(), v[i]);
  }
  return {world[0], world[1], world[2]};
}

Point2 FaceFrame::to_frame(const Point3& p) const {
  return from_exact<Point2>(to_frame(exact_value(p)));
}

Point3 FaceFrame::to_world(const Point2& q) const {
  return from_exact<Point3>(to_world(exact_value(q)));
}

Vec3d FaceFrame::unit_u() const {
  return unit(u_);
}
Vec3d FaceFrame::unit_v() const {
  return unit(v_);
}

}  // namespace penumbra
