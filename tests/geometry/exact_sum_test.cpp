// Lazy exact sums (exact_sum.h): the exact value against the terms added one by one, the
// interval and the rounded double against that value, on random rationals (fixed seed) and on
// sums that are exactly doubles or cancel.

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
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

// A rational on the grid: floor <= x 2^k < floor + 1, equal exactly when exact; for random
// rationals, doubles' dyadic values, and powers of two finer than the grid.
BOOST_AUTO_TEST_CASE(grid_floors_bracket_the_value) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(20261208);
  std::mt19937 engine(20261208);
  std::vector<Rational> values{Rational(0),
                               Rational(-3, 4),
                               Rational(5, 3),
                               Rational(-5, 3),
                               Rational(1, mpz_class(1) << 130),
                               Rational(-1, mpz_class(1) << 128),
                               Rational(0.1),
                               Rational(-1e-30)};
  for (int k = 0; k < 300; ++k) values.push_back(random_rational(random, engine, 1 + k % 200));
  const Rational unit(mpz_class(1) << kEnclosureBits);
  for (const Rational& x : values) {
    const GridFloor grid = GridFloor::of(x);
    const Rational scaled = x * unit;
    BOOST_TEST_CONTEXT(x) {
      BOOST_TEST(Rational(grid.floor) <= scaled);
      BOOST_TEST(scaled < Rational(grid.floor + 1));
      BOOST_TEST(grid.exact == (Rational(grid.floor) == scaled));
    }
  }
}

// Twice a ring's area enclosed from its corners on the grid holds the rational shoelace sum
// (written out here), and its sign, when it gives one, is that sum's: random rings of random
// rationals, of doubles, and of both, with their reversals and rings of cancelling area.
BOOST_AUTO_TEST_CASE(shoelace_enclosures_hold_the_rational_shoelace) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(7);
  std::mt19937 engine(7);
  const Rational unit(mpz_class(1) << kEnclosureBits);
  std::size_t decided = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 3 + engine() % 9;
    std::vector<std::array<Rational, 2>> ring;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<Rational, 2> p;
      for (Rational& c : p)
        c = trial % 3 == 1 ? Rational(std::ldexp(double(engine() % 4096) - 2048, -7))
                           : random_rational(random, engine, 1 + trial % 90);
      ring.push_back(p);
    }
    if (trial % 5 == 4) {  // back over itself: area zero
      const std::vector<std::array<Rational, 2>> there(ring.begin() + 1, ring.end() - 1);
      ring.insert(ring.end(), there.rbegin(), there.rend());
    }
    for (int reversed = 0; reversed < 2; ++reversed) {
      Rational twice = 0;
      ShoelaceEnclosure enclosure;
      std::vector<std::array<GridFloor, 2>> grid;
      for (const auto& p : ring) grid.push_back({GridFloor::of(p[0]), GridFloor::of(p[1])});
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::size_t j = (i + 1) % ring.size();
        twice += ring[i][0] * ring[j][1] - ring[j][0] * ring[i][1];
        enclosure.add_edge(grid[i][0], grid[i][1], grid[j][0], grid[j][1]);
      }
      const Enclosure area = enclosure.area();
      Rational scaled = twice * unit;
      scaled /= Rational(2);
      BOOST_TEST_CONTEXT("trial " << trial << (reversed ? " reversed" : "")) {
        BOOST_TEST(Rational(area.lower) <= scaled);
        BOOST_TEST(scaled <= Rational(area.upper));
        if (const std::optional<int> sign = enclosure.sign()) {
          ++decided;
          BOOST_TEST(*sign == sgn(twice));
        }
      }
      std::reverse(ring.begin(), ring.end());
    }
  }
  BOOST_TEST(decided > 600u);  // most signs are decided by the enclosure

  // A triangle finer than the grid: every corner's floor is 0 and none is exact, so the sum
  // is 0 and only the bound's a_i b_j terms say that it may not be.
  const Rational tiny(1, mpz_class(3) << 130);
  const std::array<std::array<Rational, 2>, 3> triangle{
      {{tiny, tiny}, {2 * tiny, tiny}, {tiny, 2 * tiny}}};
  ShoelaceEnclosure fine;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& p = triangle[i];
    const auto& q = triangle[(i + 1) % 3];
    fine.add_edge(GridFloor::of(p[0]), GridFloor::of(p[1]), GridFloor::of(q[0]),
                  GridFloor::of(q[1]));
  }
  BOOST_TEST(!fine.sign().has_value());
}

BOOST_AUTO_TEST_SUITE_END()
