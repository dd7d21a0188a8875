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
#include <utility>
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

// A number x on the enclosures' grid: floor = x 2^kEnclosureBits rounded down, exact when
// nothing was rounded away.
struct GridFloor {
  mpz_class floor = 0;
  bool exact = true;

  static GridFloor of(const Rational& x);
};

// Twice the signed area of a ring (the shoelace formula) enclosed in integers, summed edge by
// edge from its corners on the grid (docs/performance.md, "Sums of areas"). Writing each
// coordinate x = (X + a) 2^-k, X = floor(x 2^k), 0 <= a < 1, an edge's term x_i y_j - x_j y_i
// is 2^-2k times X_i Y_j - X_j Y_i plus X_i b_j + a_i Y_j + a_i b_j - X_j b_i - a_j Y_i - a_j b_i,
// whose size is below |X_i| + |Y_j| + 1 + |X_j| + |Y_i| + 1, less what a zero a or b leaves out
// (coordinates on the grid, such as doubles, add nothing): then |2^2k twice - sum| <= bound.
class ShoelaceEnclosure {
 public:
  // adds the term of the edge from corner (xi, yi) to corner (xj, yj).
  void add_edge(const GridFloor& xi, const GridFloor& yi, const GridFloor& xj, const GridFloor& yj);
  // adds the edges between corner(0), corner(1), ..., corner(count - 1) in turn (a ring
  // repeats its first corner last), each corner (a RationalPoint2) rounded to the grid once.
  template <typename Corner>
  void add_path(std::size_t count, const Corner& corner) {
    if (count < 2) return;
    GridFloor x = GridFloor::of(corner(0).x()), y = GridFloor::of(corner(0).y());
    for (std::size_t i = 1; i < count; ++i) {
      const auto& next = corner(i);
      GridFloor nx = GridFloor::of(next.x()), ny = GridFloor::of(next.y());
      add_edge(x, y, nx, ny);
      x = std::move(nx);
      y = std::move(ny);
    }
  }
  void add(const ShoelaceEnclosure& other);
  // takes off what other added (its bound still adds).
  void remove(const ShoelaceEnclosure& other);
  // returns the sign of twice the area when the enclosure decides it, else nothing.
  std::optional<int> sign() const;
  // returns an enclosure of the area (half of twice the area).
  Enclosure area() const;

 private:
  mpz_class sum_ = 0, bound_ = 0;
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
