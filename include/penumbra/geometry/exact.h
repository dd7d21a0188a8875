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

}  // namespace penumbra
