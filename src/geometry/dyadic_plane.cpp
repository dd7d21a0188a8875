#include "penumbra/geometry/dyadic_plane.h"

#include "dyadic_vector.h"

namespace penumbra {
namespace {

using detail::Dyadic;
using detail::Dyadic3;

template <class Object>
std::optional<Double3> doubles_of(const Object& object) {
  const auto& approx = object.approx();
  Double3 x;
  for (int i = 0; i < 3; ++i) {
    if (!approx[i].is_point()) return std::nullopt;
    x[i] = approx[i].inf();
  }
  return x;
}

// the plane with normal through p, d = -normal.p, turned so that inside is not on its
// positive side; nothing for a null normal.
std::optional<Plane3> oriented(const Dyadic3& normal, const Double3& p, const Double3& inside) {
  if (normal[0].is_zero() && normal[1].is_zero() && normal[2].is_zero()) return std::nullopt;
  const Dyadic d = -detail::dot(normal, detail::dyadic(p));
  const bool turn = (detail::dot(normal, detail::dyadic(inside)) + d).sign() > 0;
  const auto coefficient = [&](const Dyadic& x) { return turn ? Rational(-x) : Rational(x); };
  return from_exact<Plane3>(RationalPlane3(coefficient(normal[0]), coefficient(normal[1]),
                                           coefficient(normal[2]), coefficient(d)));
}

}  // namespace

std::optional<Double3> double_coordinates(const Point3& p) {
  return doubles_of(p);
}
std::optional<Double3> double_coordinates(const Vector3& v) {
  return doubles_of(v);
}

std::optional<Plane3> oriented_plane(const Double3& p, const Double3& q, const Double3& r,
                                     const Double3& inside) {
  return oriented(detail::cross(detail::difference(q, p), detail::difference(r, p)), p, inside);
}

std::optional<Plane3> oriented_plane_along(const Double3& p, const Double3& q,
                                           const Double3& direction, const Double3& inside) {
  return oriented(detail::cross(detail::difference(q, p), detail::dyadic(direction)), p, inside);
}

}  // namespace penumbra
