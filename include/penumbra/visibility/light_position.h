#pragma once
// The position of a point or directional source in homogeneous coordinates
// (q, w): a point light is (Q, 1); the sun is the point at infinity (-d, 0), d the
// direction its light travels. Nishita 1985 section 2 treats a parallel source as
// one "specified only by a direction"; with homogeneous coordinates the shadow
// code is the same for both (docs/shadows.md), with no far-away approximation.

#include <optional>

#include "penumbra/geometry/dyadic_plane.h"
#include "penumbra/geometry/kernel.h"

namespace penumbra {

class LightPosition {
 public:
  // builds a point source at position.
  static LightPosition at(const Point3& position);
  // builds a directional source whose light travels along travel (not normalised).
  // Precondition: travel is not the null vector.
  static LightPosition toward(const Vector3& travel);

  bool at_infinity() const { return !point_.has_value(); }
  // the point source's position. Precondition: !at_infinity().
  const Point3& point() const { return *point_; }
  // the direction the light travels (from the source toward the scene); for a
  // point source it is undefined. Precondition: at_infinity().
  const Vector3& travel() const { return travel_; }

  // returns the sign of F(S, Q~) = n.q + d w for the plane F = n.X + d (Nishita
  // eq. 3 extended to homogeneous Q~): POSITIVE when the source is strictly on the
  // outer side of the plane. For the sun, sign(-n . travel).
  CGAL::Sign side_of(const Plane3& plane) const;

  // returns the plane through the line (a, b) and the source, oriented so that
  // inside is on its negative side; nullopt when the source is on the line.
  // Precondition: inside is not on the plane.
  std::optional<Plane3> plane_through(const Point3& a, const Point3& b, const Point3& inside) const;

 private:
  std::optional<Point3> point_;
  Vector3 travel_;
  // the position (or travel) as doubles, when it is: planes are then built in dyadics.
  std::optional<Double3> doubles_;
};

}  // namespace penumbra
