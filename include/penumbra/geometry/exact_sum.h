#pragma once
// Exact sums of many rationals, evaluated when their exact value is asked for (the area of
// a region is the sum of its polygons' areas, docs/performance.md "Sums of areas").
//
// The exact sum of n rationals of unrelated denominators has a denominator of about n times
// their size, and adding them one by one costs a gcd of that size at every step: the area of
// one part of the ground of a sun-hours study (10^3 polygons, 10^5-bit denominators) took
// seconds. An exact_sum instead keeps what its exact value is made from and an enclosure
// of it in integers, each term rounded down and up to a multiple of 2^-kEnclosureBits. The
// enclosure gives the Epeck number its interval, and usually the double an output prints (the value
// rounded toward zero, as the exact value's own conversion rounds): when both ends of the
// enclosure round to the same double, so does every number between them. The exact value,
// when something needs it, is the terms added pairwise (a balanced tree), computed once.

#include <functional>
#include <optional>
#include <vector>

#include "penumbra/geometry/exact.h"

namespace penumbra {

// The enclosures' unit is 2^-kEnclosureBits.
constexpr unsigned kEnclosureBits = 128;

// An enclosure of a number x: lower <= x 2^kEnclosureBits <= upper.
struct Enclosure {
  mpz_class lower = 0, upper = 0;

  // returns the enclosure of x: x 2^kEnclosureBits rounded down and up (equal when x lies on
  // the grid, as every double of at most kEnclosureBits fraction bits does).
  static Enclosure of(const Rational& x);
  bool exact() const { return lower == upper; }

  void add(const Enclosure& other) {
    lower += other.lower;
    upper += other.upper;
  }
};

// returns the sum of terms (exact_sum results or any other Epeck numbers) as an Epeck number
// whose exact value is computed on first use; the enclosures of exact_sum terms are added,
// the exact values of the others are taken.
Exact exact_sum(const std::vector<Exact>& terms);

// returns the sum of numbers enclosed by terms, whose exact value exact() computes when first
// asked for (the polygons' areas of a region, from their rings).
Exact exact_sum(const std::vector<Enclosure>& terms, std::function<Rational()> exact);

// returns the exact sum of values, added pairwise (each addition meets numbers of like size).
Rational pairwise_sum(std::vector<Rational> values);

// returns the enclosure of x when x is an exact_sum, else nothing.
std::optional<Enclosure> enclosure_of(const Exact& x);

// returns x's exact value rounded toward zero to a double (what CGAL::to_double does with the
// rational), without computing it when x is an exact_sum whose enclosure decides it;
// nothing when it does not.
std::optional<double> truncated_to_double(const Exact& x);

}  // namespace penumbra
