#pragma once
// The local 2D frame of a face (DESIGN.md, "Conventions"): origin o, axes u and v
// with u x v a positive multiple of the outward normal, so counter-clockwise in the
// frame is counter-clockwise seen from outside. The exact frame is orthogonal but
// not normalised (normalising needs square roots): u runs along the face's first
// edge, v = n x u. Frame coordinates (s, t) name the point o + s u + t v, so they
// are exact rationals; outputs give the normalised axes in doubles.

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/kernel.h"

namespace penumbra {

class FaceFrame {
 public:
  FaceFrame() = default;
  // builds the frame at origin with first axis along u_direction, in the plane of normal.
  // v and the squared lengths are lazy constructions of depth one or two over the
  // arguments: computed exactly only if a query needs them.
  FaceFrame(const Point3& origin, const Vector3& u_direction, const Vector3& normal);

  // builds the frame from its exact parts: u, v = n x u and their squared lengths
  // (precondition: they are that).
  FaceFrame(const Point3& origin, RationalVector3 u, RationalVector3 v, Rational uu, Rational vv);

  const Point3& origin() const { return origin_; }
  const Vector3& u() const { return u_; }
  const Vector3& v() const { return v_; }
  // u . u and v . v, exactly.
  const Exact& squared_u() const { return uu_; }
  const Exact& squared_v() const { return vv_; }

  // returns the frame coordinates of a point of the plane (of any point: its
  // orthogonal projection's coordinates), computed in rationals.
  Point2 to_frame(const Point3& p) const;

  // returns the world point with frame coordinates q, computed in rationals.
  Point3 to_world(const Point2& q) const;

  // the same on rational values (no Epeck object made).
  RationalPoint2 to_frame(const RationalPoint3& p) const;
  RationalPoint3 to_world(const RationalPoint2& q) const;

  // true when other is a copy of this frame (the same exact objects, not merely equal).
  bool same_as(const FaceFrame& other) const {
    return CGAL::identical(origin_, other.origin_) && CGAL::identical(u_, other.u_) &&
           CGAL::identical(v_, other.v_);
  }

  // the unit axes, rounded to doubles, for output.
  Vec3d unit_u() const;
  Vec3d unit_v() const;

 private:
  Point3 origin_;
  Vector3 u_;
  Vector3 v_;
  Exact uu_;  // u . u
  Exact vv_;  // v . v
};

}  // namespace penumbra
