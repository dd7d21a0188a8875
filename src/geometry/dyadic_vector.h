#pragma once
// Vectors of dyadic numbers (CGAL::Mpzf, a double-sized mantissa grown as needed and a
// binary exponent): differences, sums and products of doubles are exact and need no gcd,
// so constructions from double coordinates (planes, frames) are computed here and turned
// into rationals once (geometry/exact.h).

#include <CGAL/Mpzf.h>

#include <array>

#include "penumbra/geometry/exact.h"

namespace penumbra::detail {

using Dyadic = CGAL::Mpzf;
using Dyadic3 = std::array<Dyadic, 3>;

inline Dyadic3 dyadic(const std::array<double, 3>& x) {
  return {Dyadic(x[0]), Dyadic(x[1]), Dyadic(x[2])};
}
inline Dyadic3 difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {Dyadic(a[0]) - Dyadic(b[0]), Dyadic(a[1]) - Dyadic(b[1]), Dyadic(a[2]) - Dyadic(b[2])};
}
inline Dyadic3 cross(const Dyadic3& a, const Dyadic3& b) {
  return {a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]};
}
inline Dyadic dot(const Dyadic3& a, const Dyadic3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline RationalVector3 rational_vector(const Dyadic3& a) {
  return RationalVector3(Rational(a[0]), Rational(a[1]), Rational(a[2]));
}

}  // namespace penumbra::detail
