#include "algebraic.h"

#include <gmp.h>

namespace penumbra::detail {
namespace {

// the GMP value of a rational, whichever of CGAL's GMP rationals Epeck uses.
[[maybe_unused]] mpq_srcptr gmp(const CGAL::Gmpq& x) {
  return x.mpq();
}
#ifdef CGAL_USE_GMPXX
[[maybe_unused]] mpq_srcptr gmp(const mpq_class& x) {
  return x.get_mpq_t();
}
#endif

// the rational n / 1.
Rational of_integer(const mpz_t n) {
  mpq_t q;
  mpq_init(q);
  mpq_set_z(q, n);
  Rational result(q);
  mpq_clear(q);
  return result;
}

}  // namespace

const AlgebraicKernel& algebraic_kernel() {
  static const AlgebraicKernel kernel;
  return kernel;
}

CORE::BigRat bound(const Rational& x) {
  return CORE::BigRat(gmp(x));
}

Rational rational(const CORE::BigRat& x) {
  return Rational(x.get_mp());
}

Algebraic algebraic(const Rational& x) {
  return Algebraic(bound(x));
}

AlgebraicKernel::Polynomial_1 integer_polynomial(const Poly& p) {
  mpz_t scale;
  mpz_init_set_ui(scale, 1);
  for (const Rational& c : p.c) mpz_lcm(scale, scale, mpq_denref(gmp(c)));
  std::vector<CORE::BigInt> coefficients;
  for (const Rational& c : p.c) {
    mpz_t n;
    mpz_init(n);
    mpz_divexact(n, scale, mpq_denref(gmp(c)));
    mpz_mul(n, n, mpq_numref(gmp(c)));
    coefficients.emplace_back(n);
    mpz_clear(n);
  }
  mpz_clear(scale);
  return AlgebraicKernel::Polynomial_1(coefficients.begin(), coefficients.end());
}

Poly squarefree_primitive(const Poly& p) {
  std::vector<Rational> slope;
  for (std::size_t k = 1; k < p.c.size(); ++k) slope.push_back(p.c[k] * Rational(int(k)));
  const Poly part = exact_quotient(p, gcd(p, Poly(std::move(slope))));
  mpz_t scale, content;
  mpz_init_set_ui(scale, 1);
  mpz_init_set_ui(content, 0);
  for (const Rational& c : part.c) mpz_lcm(scale, scale, mpq_denref(gmp(c)));
  std::vector<Rational> integers;
  for (const Rational& c : part.c) {
    integers.push_back(c * of_integer(scale));
    mpz_gcd(content, content, mpq_numref(gmp(integers.back())));
  }
  if (mpz_sgn(mpq_numref(gmp(integers.back()))) < 0) mpz_neg(content, content);
  const Rational divisor = of_integer(content);
  for (Rational& c : integers) c /= divisor;
  mpz_clear(scale);
  mpz_clear(content);
  return Poly(std::move(integers));
}

std::vector<Algebraic> all_roots(const Poly& p) {
  std::vector<Algebraic> result;
  if (p.degree() < 1) return result;
  std::vector<std::pair<Algebraic, AlgebraicKernel::Multiplicity_type>> roots;
  algebraic_kernel().solve_1_object()(integer_polynomial(p), std::back_inserter(roots));
  for (const auto& root : roots) result.push_back(root.first);
  return result;
}

Rational rational_between(const Algebraic& low, const Algebraic& high) {
  return rational(algebraic_kernel().bound_between_1_object()(low, high));
}

std::pair<Rational, Rational> enclosure(const Algebraic& x, int bits) {
  const auto [low, high] = algebraic_kernel().approximate_absolute_1_object()(x, bits);
  return {rational(low), rational(high)};
}

double approximate(const Algebraic& x) {
  return CGAL::to_double(x);
}

}  // namespace penumbra::detail
