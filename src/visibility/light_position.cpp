#include "penumbra/visibility/light_position.h"

namespace penumbra {

LightPosition LightPosition::at(const Point3& position) {
  LightPosition light;
  light.point_ = position;
  light.doubles_ = double_coordinates(position);
  return light;
}

LightPosition LightPosition::toward(const Vector3& travel) {
  CGAL_precondition(travel != CGAL::NULL_VECTOR);
  LightPosition light;
  light.travel_ = travel;
  light.doubles_ = double_coordinates(travel);
  return light;
}

CGAL::Sign LightPosition::side_of(const Plane3& plane) const {
  if (point_) return static_cast<CGAL::Sign>(plane.oriented_side(*point_));
  // Q~ = (-travel, 0): F(S, Q~) = -(n . travel).
  return CGAL::opposite(CGAL::sign(plane.orthogonal_vector() * travel_));
}

std::optional<Plane3> LightPosition::plane_through(const Point3& a, const Point3& b,
                                                   const Point3& inside) const {
  // Doubles (the usual case): the same plane, its rationals computed once.
  if (doubles_) {
    const auto x = double_coordinates(a), y = double_coordinates(b), z = double_coordinates(inside);
    if (x && y && z)
      return point_ ? oriented_plane(*x, *y, *doubles_, *z)
                    : oriented_plane_along(*x, *y, *doubles_, *z);
  }
  if (point_) {
    if (CGAL::collinear(a, b, *point_)) return std::nullopt;
    // Plane3(a, b, Q): a, b, Q counter-clockwise seen from the positive side.
    const Plane3 plane(a, b, *point_);
    return plane.oriented_side(inside) == CGAL::ON_POSITIVE_SIDE ? plane.opposite() : plane;
  }
  const Vector3 normal = CGAL::cross_product(b - a, travel_);
  if (normal == CGAL::NULL_VECTOR) return std::nullopt;
  const Plane3 plane(a, normal);
  return plane.oriented_side(inside) == CGAL::ON_POSITIVE_SIDE ? plane.opposite() : plane;
}

}  // namespace penumbra
