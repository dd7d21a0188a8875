#pragma once
// Interval arithmetic for the filters in front of exact tests ("exact numbers only where
// needed", docs/performance.md): CGAL's interval numbers, which enclose the exact value of
// what they compute when the FPU rounds upward (CGAL::Protect_FPU_rounding<true>). A sign
// an interval certifies is the exact sign; a sign it cannot certify is left to rationals.
// No epsilon decides anything.

#include <CGAL/Interval_nt.h>

#include <array>
#include <type_traits>
#include <utility>

namespace penumbra {

using Interval = CGAL::Interval_nt<false>;
using IntervalPoint = std::array<Interval, 3>;

// returns F(x) = a x[0] + b x[1] + c x[2] + d, the value of plane (a, b, c, d) at x (Nishita
// 1985 eq. 3). Works for every plane with a()..d() (an exact plane, its interval or rational
// approximation) and every point indexed by [] (Vec3d, IntervalPoint, CGAL points); in
// interval arithmetic it needs upward rounding.
// The result has the type of the plane's coefficients (evaluated there, so that no
// expression template of gmpxx outlives its operands).
template <class Plane, class Point>
std::decay_t<decltype(std::declval<const Plane&>().a())> plane_value(const Plane& plane,
                                                                     const Point& x) {
  using Value = std::decay_t<decltype(plane.a())>;
  return Value(plane.a() * x[0] + plane.b() * x[1] + plane.c() * x[2] + plane.d());
}

// returns n . x for a normal n given by its three components a(), b(), c().
template <class Plane, class Vector>
std::decay_t<decltype(std::declval<const Plane&>().a())> normal_dot(const Plane& plane,
                                                                    const Vector& x) {
  using Value = std::decay_t<decltype(plane.a())>;
  return Value(plane.a() * x[0] + plane.b() * x[1] + plane.c() * x[2]);
}

// Vectors of intervals (points and directions alike); all need upward rounding.
inline IntervalPoint minus(const IntervalPoint& a, const IntervalPoint& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

inline IntervalPoint cross(const IntervalPoint& a, const IntervalPoint& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline Interval dot(const IntervalPoint& a, const IntervalPoint& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// returns the interval enclosure of an exact point's coordinates (its approximation).
template <class ExactPoint>
IntervalPoint interval_point(const ExactPoint& p) {
  const auto& approx = p.approx();
  return {approx.x(), approx.y(), approx.z()};
}

}  // namespace penumbra
