#pragma once
// The interval enclosure of a rational, for the filters in front of the joint umbra's exact
// tests (convex_ring.h, blocked_interval_filter.h). CGAL's to_interval goes through MPFR for
// every rational; most of the sweep's rationals have a numerator and a denominator of at
// most 53 bits, which doubles hold exactly, and for those one division decides it: the
// quotient q = n / d is rounded (in any rounding mode, so also under the filters' upward
// rounding) to a neighbour of n / d, and the remainder n - q d is a double computed exactly
// by one fused multiply-add, whose sign says on which side of q the rational lies. Others go
// to CGAL. Both give an interval that holds the rational; this one is at most one ulp wide.

#include <array>
#include <cmath>
#include <limits>

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

namespace penumbra::detail {

inline Interval enclosure(const Rational& x) {
  const mpz_srcptr n = x.get_num_mpz_t(), d = x.get_den_mpz_t();
  if (mpz_sizeinbase(n, 2) > 53 || mpz_sizeinbase(d, 2) > 53) return Interval(CGAL::to_interval(x));
  const double nd = mpz_get_d(n), dd = mpz_get_d(d);  // exact: at most 53 bits each
  const double q = nd / dd;
  const double remainder = std::fma(-q, dd, nd);  // n - q d, exact (d > 0)
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (remainder > 0) return Interval(q, std::nextafter(q, infinity));
  if (remainder < 0) return Interval(std::nextafter(q, -infinity), q);
  return Interval(q);
}

// the enclosures of a plane's coefficients a, b, c, d.
inline std::array<Interval, 4> enclosure(const RationalPlane3& h) {
  return {enclosure(h.a()), enclosure(h.b()), enclosure(h.c()), enclosure(h.d())};
}

}  // namespace penumbra::detail
