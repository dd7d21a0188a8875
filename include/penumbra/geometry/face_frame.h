#pragma once
// The local 2D frame of a face (DESIGN.md, "Conventions"): origin o, axes u and v
// with u x v a positive multiple of the outward normal, so counter-clockwise in the
// frame is counter-clockwise seen from outside. The exact frame is orthogonal but
// not normalised (normalising needs square roots): u runs along the face's first
// edge, v = n x u. Frame coordinates (s, t) name the point o + s u + t v, so they
// are exact rationals; outputs give the normalised axes in doubles.

#include "penumbra/geometry/kernel.h"

namespace penumbra {

class FaceFrame {
 public:
  FaceFrame() = default;
  // builds the frame at origin with first axis along u_direction, in the plane of normal.
  FaceFrame(const Point3& origin, const Vector3& u_direction, const Vector3& normal)
      : origin_(origin),
        u_(u_direction),
        v_(CGAL::cross_product(normal, u_direction)),
        uu_(u_ * u_),
        vv_(v_ * v_) {}

  const Point3& origin() const { return origin_; }
  const Vector3& u() const { return u_; }
  const Vector3& v() const { return v_; }

  // returns the frame coordinates of a point of the plane (of any point: its
  // orthogonal projection's coordinates).
  Point2 to_frame(const Point3& p) const {
    const Vector3 d = p - origin_;
    return Point2((d * u_) / uu_, (d * v_) / vv_);
  }

  // returns the world point with frame coordinates q.
  Point3 to_world(const Point2& q) const { return origin_ + q.x() * u_ + q.y() * v_; }

  // the unit axes, rounded to doubles, for output.
  Vec3d unit_u() const;
  Vec3d unit_v() const;

 private:
  Point3 origin_;
  Vector3 u_;
  Vector3 v_;
  Exact uu_;
  Exact vv_;
};

}  // namespace penumbra
