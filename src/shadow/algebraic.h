#pragma once
// Real algebraic numbers for the joint umbra (exact_umbra.h): CGAL's univariate algebraic
// kernel over CORE's integers, which isolates the real roots of the sweep's polynomials
// (pencil.h) and compares them exactly.

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_BigInt.h>

#include <utility>
#include <vector>

#include "pencil.h"
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {

using AlgebraicKernel = CGAL::Algebraic_kernel_d_1<CORE::BigInt>;
using Algebraic = AlgebraicKernel::Algebraic_real_1;

const AlgebraicKernel& algebraic_kernel();

// the GMP rational of x, and back.
CORE::BigRat bound(const Rational& x);
Rational rational(const CORE::BigRat& x);
Algebraic algebraic(const Rational& x);

// returns p with integer coefficients (times the common denominator): the same roots.
AlgebraicKernel::Polynomial_1 integer_polynomial(const Poly& p);
// the squarefree part of p with integer coefficients, primitive, leading coefficient
// positive: the same roots, written one way (p not constant).
Poly squarefree_primitive(const Poly& p);
// the real roots of p, increasing and distinct (none for a constant or zero p).
std::vector<Algebraic> all_roots(const Poly& p);
// returns a rational strictly between low < high.
Rational rational_between(const Algebraic& low, const Algebraic& high);
// returns rationals low <= x <= high with high - low <= 2^-bits.
std::pair<Rational, Rational> enclosure(const Algebraic& x, int bits);
double approximate(const Algebraic& x);

}  // namespace penumbra::detail
