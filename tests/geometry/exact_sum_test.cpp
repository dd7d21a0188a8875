// Lazy exact sums (exact_sum.h): the exact value against the terms added one by one, the
// interval and the rounded double against that value, on random rationals (fixed seed) and on
// sums that are exactly doubles or cancel.

#include <boost/test/unit_test.hpp>

#include <random>

#include "penumbra/geometry/exact_sum.h"

using namespace penumbra;

namespace {

// returns a random rational of numerator and denominator of up to bits bits, of either sign.
Rational random_rational(gmp_randclass& random, std::mt19937& engine, unsigned bits) {
  mpz_class numerator = random.get_z_bits(1 + engine() % bits);
  mpz_class denominator = random.get_z_bits(1 + engine() % bits) + 1;
  if (engine() % 2) numerator = -numerator;
  Rational x(numerator, denominator);
  x.canonicalize();
  return x;
}

// returns the sum of terms made lazily (each term an Epeck number holding it).
Exact lazy_sum(const std::vector<Rational>& terms) {
  std::vector<Exact> numbers;
  for (const Rational& term : terms) numbers.push_back(exact_number(term));
  return exact_sum(numbers);
}

Rational one_by_one(const std::vector<Rational>& terms) {
  Rational sum = 0;
  for (const Rational& term : terms) sum += term;
  return sum;
}

// checks sum against expected: its exact value, its interval, and the double it rounds to
// (toward zero, as mpq_get_d does) when the enclosure decides it. returns whether it did.
bool check_sum(const Exact& sum, const Rational& expected) {
  const std::optional<Enclosure> enclosure = enclosure_of(sum);
  BOOST_TEST_REQUIRE(enclosure.has_value());
  const Rational scaled = expected * Rational(mpz_class(1) << kEnclosureBits);
  BOOST_TEST(Rational(enclosure->lower) <= scaled);
  BOOST_TEST(scaled <= Rational(enclosure->upper));
  const std::optional<double> decided = truncated_to_double(sum);
  const CGAL::Interval_nt<false> interval = sum.approx();  // before the exact value refines it
  BOOST_TEST(Rational(interval.inf()) <= expected);
  BOOST_TEST(expected <= Rational(interval.sup()));
  if (decided) BOOST_TEST(*decided == expected.get_d());
  BOOST_TEST(CGAL::exact(sum) == expected);
  return decided.has_value();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_sum_of_rationals)

BOOST_AUTO_TEST_CASE(random_sums_equal_the_terms_added_one_by_one) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(1985);
  std::mt19937 engine(1985);
  int sums = 0, decided = 0;
  for (std::size_t n : {1, 2, 3, 7, 64, 300}) {
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<Rational> terms;
      for (std::size_t k = 0; k < n; ++k) terms.push_back(random_rational(random, engine, 64));
      const Rational expected = one_by_one(terms);
      ++sums;
      decided += check_sum(lazy_sum(terms), expected);
    }
  }
  // The enclosure is 2^-128 per term wide: a random sum lies that close to a double's
  // boundary with probability ~n 2^-75, so the enclosure decides them all.
  BOOST_TEST(decided == sums);
}

BOOST_AUTO_TEST_CASE(sums_of_sums_add_their_enclosures) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(1980);
  std::mt19937 engine(1980);
  std::vector<Exact> parts;
  std::vector<Rational> all;
  for (int part = 0; part < 12; ++part) {
    std::vector<Rational> terms;
    for (int k = 0; k < 40; ++k) terms.push_back(random_rational(random, engine, 90));
    all.insert(all.end(), terms.begin(), terms.end());
    parts.push_back(lazy_sum(terms));
  }
  // Plain numbers among the terms: one lazy (a product whose exact value is not computed),
  // one made from a double.
  const Exact product = Exact(1) / Exact(3) * Exact(7);
  parts.push_back(product);
  all.push_back(Rational(7, 3));
  parts.push_back(Exact(0.125));
  all.push_back(Rational(1, 8));
  BOOST_TEST(check_sum(exact_sum(parts), one_by_one(all)));
  // Asking a part for its exact value first changes nothing.
  BOOST_TEST(CGAL::exact(parts.front()) == one_by_one({all.begin(), all.begin() + 40}));
  BOOST_TEST(check_sum(exact_sum(parts), one_by_one(all)));
}

BOOST_AUTO_TEST_CASE(a_sum_that_is_a_double_rounds_to_itself) {
  // 1/3 + 2/3 + 23 = 24: floor(2^128 / 3) + floor(2^129 / 3) = 2^128 - 1, so the enclosure
  // straddles 24 and cannot say whether the value is 24 or just below (rounded toward zero,
  // just below would give the double before 24): the exact value decides.
  const Exact thirds = lazy_sum({Rational(1, 3), Rational(2, 3), 23});
  BOOST_TEST(!truncated_to_double(thirds).has_value());
  BOOST_TEST(check_sum(thirds, 24) == false);
  // Dyadic terms of few bits are on the enclosure's grid: the enclosure is the value.
  const Exact quarters = lazy_sum({Rational(1, 2), Rational(1, 4), 23.25});
  BOOST_TEST(truncated_to_double(quarters).value_or(0) == 24.0);
  BOOST_TEST(check_sum(quarters, 24));
}

BOOST_AUTO_TEST_CASE(cancelling_terms_keep_their_sign) {
  // a - a + 10^-60 and a - a - 10^-60: far below the enclosure's 2^-128 grid, so the
  // interval holds zero and the sign (a filtered predicate) asks for the exact value.
  const Rational a(mpz_class("123456789012345678901234567890"), mpz_class("7"));
  const Rational tiny(1, mpz_class("1" + std::string(60, '0')));
  const Exact up = lazy_sum({a, -a, tiny});
  const Exact down = lazy_sum({a, tiny - a - tiny - tiny});
  BOOST_TEST(CGAL::sign(up) == CGAL::POSITIVE);
  BOOST_TEST(CGAL::sign(down) == CGAL::NEGATIVE);
  BOOST_TEST(CGAL::exact(up) == tiny);
  BOOST_TEST(CGAL::exact(down) == -tiny);
  // Nothing at all: zero.
  BOOST_TEST(check_sum(lazy_sum({}), 0));
}

BOOST_AUTO_TEST_SUITE_END()
