#pragma once
// Exact values without lazy chains ("exact numbers only where needed",
// docs/performance.md): the rational kernel behind Epeck, and Epeck objects made from
// rational values computed once. A lazy construction (p - q, cross products, divisions)
// records a node whose exact value is computed on first use, each under its own
// std::call_once; a chain of them costs a memory allocation, a rational operation and a
// system call per node. Where a construction's exact value will be needed anyway, it is
// cheaper to compute it in rationals directly and wrap the result (same value, so every
// later decision is the same).

#include <array>
#include <atomic>
#include <cmath>
#include <type_traits>
#include <utility>

#include "penumbra/geometry/kernel.h"

namespace penumbra {

using ExactKernel = Kernel::Exact_kernel;  // Simple_cartesian over GMP rationals
using Rational = Exact::ET;
using RationalPoint3 = ExactKernel::Point_3;
using RationalVector3 = ExactKernel::Vector_3;
using RationalPlane3 = ExactKernel::Plane_3;
using RationalPoint2 = ExactKernel::Point_2;

// returns the Epeck object whose exact value is value: its interval approximation is
// computed from it, and no lazy construction stands behind it.
template <class Lazy, class Value>
Lazy from_exact(Value&& value) {
  return Lazy(typename Lazy::Rep(std::forward<Value>(value)));
}

// returns the representation behind an Epeck object.
template <class Lazy>
const typename Lazy::Self_rep* lazy_rep(const Lazy& x) {
  return static_cast<const typename Lazy::Self_rep*>(
      static_cast<const CGAL::Rep*>(x.for_compact_container()));
}

// returns CGAL::exact(x), without the system call CGAL makes on the first exact() of each
// object. Lazy_rep::exact() runs std::call_once even when the value is already stored (as
// from_exact and exact_number store it at construction), and glibc's first run of a
// once-flag ends in a futex wake: one system call per object, about a tenth of the time of
// a shadow computation on a mesh. A stored value is read directly here, after the acquire
// fence that pairs with the release store that published it (as Lazy_rep's destructor
// reads it); an object with no exact value yet takes CGAL's path. The same value either way.
template <class Lazy>
auto exact_value(const Lazy& x) -> decltype(CGAL::exact(x)) {
  const auto* rep = lazy_rep(x);
  if (rep->is_lazy()) return CGAL::exact(x);
  std::atomic_thread_fence(std::memory_order_acquire);
  return rep->exact_unsafe();
}

// returns whether x's exact value is stored, so that exact_value reads it without computing.
template <class Lazy>
bool has_exact_value(const Lazy& x) {
  return !lazy_rep(x)->is_lazy();
}

// returns the Epeck number whose exact value is value.
inline Exact exact_number(Rational value) {
  return Exact(std::move(value));
}

// returns true and sets x when value is exactly a double.
inline bool exact_double(const Rational& value, double& x) {
  x = CGAL::to_double(value);
  return std::isfinite(x) && Rational(x) == value;
}

// returns the Epeck point whose exact value is value, made from doubles when its coordinates
// are doubles: its approximation is then exact (a point interval), so filters decide even
// the equality of two such points without rationals, and no rational is stored.
template <class Point, class RationalPoint>
Point point_from(RationalPoint&& value) {
  constexpr int dimension = std::decay_t<RationalPoint>::Ambient_dimension::value;
  std::array<double, dimension> x;
  for (int k = 0; k < dimension; ++k)
    if (!exact_double(value[k], x[k])) return from_exact<Point>(std::forward<RationalPoint>(value));
  if constexpr (dimension == 2)
    return Point(x[0], x[1]);
  else
    return Point(x[0], x[1], x[2]);
}

// Predicates on points whose exact values are usually known already (shadow polygons from
// the receiver clip): interval arithmetic first, and rationals where the interval cannot
// decide, without the exception CGAL's filtered predicates throw and catch for every tie
// (equal points, collinear corners: the usual case in a ring).

// returns true when a and b are the same point.
inline bool same_point(const Point2& a, const Point2& b) {
  const auto &p = CGAL::approx(a), &q = CGAL::approx(b);
  if (!CGAL::possibly(p.x() == q.x()) || !CGAL::possibly(p.y() == q.y())) return false;
  // Intervals that are points are the exact values (points given as doubles).
  if (p.x().is_point() && p.y().is_point() && q.x().is_point() && q.y().is_point()) return true;
  return exact_value(a) == exact_value(b);
}

// returns the sign of the orientation of (a, b, c): POSITIVE for a left turn.
inline CGAL::Sign orientation_sign(const Point2& a, const Point2& b, const Point2& c) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    const auto &p = CGAL::approx(a), &q = CGAL::approx(b), &r = CGAL::approx(c);
    const auto value = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(value);
    if (CGAL::is_certain(sign)) return sign.make_certain();
  }
  const auto &p = exact_value(a), &q = exact_value(b), &r = exact_value(c);
  return CGAL::sign((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
}

}  // namespace penumbra
