// Exact values and the filtered point predicates of exact.h: exact_value against CGAL::exact
// and against rationals computed here, for objects whose exact value is stored and for lazy
// constructions; same_point and orientation_sign against the rational equality and the
// rational determinant, on lattices of thirds and of doubles where ties (equal points,
// collinear corners) are common (fixed seed).

#include <boost/test/unit_test.hpp>

#include <random>

#include "penumbra/geometry/exact.h"

using namespace penumbra;

namespace {

// returns n / d in lowest terms (the form every rational of the library is in).
Rational ratio(int n, int d) {
  Rational x(n, d);
  x.canonicalize();
  return x;
}

// A point of a small lattice, made in one of three ways with the same exact value: from
// doubles (its interval a point), from a stored rational, or as a lazy construction (the
// midpoint of two stored points, whose exact value is computed on first use).
struct LatticePoint {
  Point2 point;
  RationalPoint2 value;
};

LatticePoint lattice_point(std::mt19937& random) {
  std::uniform_int_distribution<int> coordinate(0, 6), way(0, 2);
  const int i = coordinate(random), j = coordinate(random);
  switch (way(random)) {
    case 0:  // halves are doubles
      return {Point2(i / 2.0, j / 2.0), RationalPoint2(ratio(i, 2), ratio(j, 2))};
    case 1: {
      const RationalPoint2 value(ratio(i, 3), ratio(j, 3));
      return {from_exact<Point2>(value), value};
    }
    default: {
      // the midpoint of (i/3 - 1, j/3) and (i/3 + 1, j/3)
      const Point2 a = from_exact<Point2>(RationalPoint2(ratio(i - 3, 3), ratio(j, 3)));
      const Point2 b = from_exact<Point2>(RationalPoint2(ratio(i + 3, 3), ratio(j, 3)));
      return {CGAL::midpoint(a, b), RationalPoint2(ratio(i, 3), ratio(j, 3))};
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_predicates)

BOOST_AUTO_TEST_CASE(exact_value_is_the_stored_or_computed_exact_value) {
  // Stored at construction.
  const RationalPoint2 stored(Rational(1, 3), Rational(-2, 7));
  const Point2 p = from_exact<Point2>(stored);
  BOOST_TEST(exact_value(p) == stored);
  BOOST_TEST(&exact_value(p) == &CGAL::exact(p));  // the same object, not a copy
  // A lazy construction: computed on first use, then read where it is stored.
  const Point2 q = from_exact<Point2>(RationalPoint2(Rational(5, 3), Rational(1, 7)));
  const Point2 middle = CGAL::midpoint(p, q);
  const RationalPoint2 expected(Rational(1), Rational(-1, 14));
  BOOST_TEST(exact_value(middle) == expected);
  BOOST_TEST(exact_value(middle) == expected);
  // Numbers: a stored rational and a lazy quotient.
  const Exact third = exact_number(Rational(1, 3));
  BOOST_TEST(exact_value(third) == Rational(1, 3));
  const Exact quotient = Exact(1) / Exact(3) + third;
  BOOST_TEST(exact_value(quotient) == Rational(2, 3));
  BOOST_TEST(exact_value(quotient) == CGAL::exact(quotient));
}

BOOST_AUTO_TEST_CASE(same_point_is_rational_equality) {
  std::mt19937 random(1980);
  int equal = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const LatticePoint a = lattice_point(random), b = lattice_point(random);
    const bool expected = a.value == b.value;
    BOOST_TEST(same_point(a.point, b.point) == expected);
    equal += expected;
  }
  BOOST_TEST(equal > 30);  // ties, which the intervals cannot decide, are exercised
}

BOOST_AUTO_TEST_CASE(orientation_sign_is_the_sign_of_the_rational_determinant) {
  std::mt19937 random(1985);
  int collinear = 0, left = 0, right = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const LatticePoint a = lattice_point(random), b = lattice_point(random),
                       c = lattice_point(random);
    const RationalPoint2 &p = a.value, &q = b.value, &r = c.value;
    const CGAL::Sign expected =
        CGAL::sign((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()));
    BOOST_TEST(orientation_sign(a.point, b.point, c.point) == expected);
    collinear += expected == CGAL::ZERO;
    left += expected == CGAL::POSITIVE;
    right += expected == CGAL::NEGATIVE;
  }
  BOOST_TEST(collinear > 100);
  BOOST_TEST(left > 1000);
  BOOST_TEST(right > 1000);
}

BOOST_AUTO_TEST_SUITE_END()
