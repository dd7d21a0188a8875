// The area of a region (canonical_region): an exact sum made lazily from integer enclosures
// of the polygons' areas (exact_sum.h), for one polygon as for many; and the sign of a ring's
// area (area_sign). Checked against the shoelace formula evaluated here in rationals, polygon
// by polygon, on random polygons with rational corners of unrelated denominators and on
// lattice rings with zero areas (fixed seeds).

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>
#include <string>

#include "penumbra/geometry/exact_sum.h"
#include "penumbra/shadow/region.h"

using namespace penumbra;

namespace {

// returns a random rational in [-range, range] with a denominator up to 10^6.
Rational random_coordinate(std::mt19937& random, int range) {
  std::uniform_int_distribution<long> denominator(1, 1000000);
  const long q = denominator(random);
  std::uniform_int_distribution<long> numerator(-range * q, range * q);
  Rational x(numerator(random), q);
  x.canonicalize();
  return x;
}

// returns n / 3 in lowest terms (the form every rational of the library is in).
Rational third(int n) {
  Rational x(n, 3);
  x.canonicalize();
  return x;
}

Point2 point_of(const Rational& x, const Rational& y) {
  return from_exact<Point2>(RationalPoint2(x, y));
}

// returns a quadrilateral around (cx, cy): four corners at random distances in the four
// quadrants, counter-clockwise (so convex or not, but simple), as rationals.
Ring2 random_quadrilateral(std::mt19937& random, const Rational& cx, const Rational& cy) {
  const auto offset = [&]() -> Rational {
    return abs(random_coordinate(random, 3)) + Rational(1, 1000);
  };
  return {point_of(cx + offset(), cy + offset()), point_of(cx - offset(), cy + offset()),
          point_of(cx - offset(), cy - offset()), point_of(cx + offset(), cy - offset())};
}

// the shoelace formula, term by term in rationals.
Rational shoelace(const Ring2& ring) {
  Rational twice = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const RationalPoint2& p = CGAL::exact(ring[k]);
    const RationalPoint2& q = CGAL::exact(ring[(k + 1) % ring.size()]);
    twice += p.x() * q.y() - p.y() * q.x();
  }
  return twice / 2;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(region_area)

BOOST_AUTO_TEST_CASE(many_polygons_add_up_to_the_sum_of_their_shoelace_areas) {
  std::mt19937 random(1985);
  int decided = 0;
  const int trials = 12;
  for (int trial = 0; trial < trials; ++trial) {
    // Up to 300 quadrilaterals, some with a hole, around centres as far as 10^4 from the
    // origin (the enclosure's error grows with the coordinates).
    std::vector<Polygon2> polygons;
    Rational expected = 0;
    const int count = 2 + trial * 25;
    const int range = trial % 2 ? 10000 : 10;
    for (int k = 0; k < count; ++k) {
      const Rational cx = random_coordinate(random, range), cy = random_coordinate(random, range);
      Polygon2 polygon{canonical_ring(random_quadrilateral(random, cx, cy)), {}};
      expected += shoelace(polygon.outer);
      if (k % 3 == 0) {
        // A hole: the triangle (cx, cy) + small offsets, clockwise, inside every quadrilateral
        // around (cx, cy) (whose corners are at least 1/1000 away on both axes).
        const Rational e(1, 4000);
        Ring2 hole{point_of(cx, cy), point_of(cx, cy + e), point_of(cx + e, cy)};
        polygon.holes.push_back(canonical_ring(hole));
        expected += shoelace(polygon.holes.back());
      }
      polygons.push_back(std::move(polygon));
    }
    const Region2 region = canonical_region(polygons);
    // The enclosure holds the value, exactly: lower <= expected 2^128 <= upper.
    const std::optional<Enclosure> enclosure = enclosure_of(region.area);
    BOOST_TEST_REQUIRE(enclosure.has_value());
    const Rational scaled = expected * Rational(mpz_class(1) << kEnclosureBits);
    BOOST_TEST(Rational(enclosure->lower) <= scaled);
    BOOST_TEST(scaled <= Rational(enclosure->upper));
    const CGAL::Interval_nt<false> interval = region.area.approx();
    BOOST_TEST(Rational(interval.inf()) <= expected);
    BOOST_TEST(expected <= Rational(interval.sup()));
    if (const std::optional<double> value = truncated_to_double(region.area)) {
      ++decided;
      BOOST_TEST(*value == expected.get_d());
    }
    BOOST_TEST(CGAL::exact(region.area) == expected);
  }
  // Each corner's enclosure is 2^-128 wide: the sums are far from a double's boundary.
  BOOST_TEST(decided == trials);
}

BOOST_AUTO_TEST_CASE(squares_with_integer_corners_have_their_integer_area) {
  // 1 x 1, 2 x 2, ..., 40 x 40 squares apart: the enclosure is the exact value (integer
  // corners are on its grid), so the double is the sum of squares n (n + 1) (2n + 1) / 6.
  std::vector<Polygon2> squares;
  for (int n = 1; n <= 40; ++n) {
    const int x = 100 * n;
    squares.push_back(
        {canonical_ring({Point2(x, 0), Point2(x + n, 0), Point2(x + n, n), Point2(x, n)}), {}});
  }
  const Region2 region = canonical_region(squares);
  BOOST_TEST(truncated_to_double(region.area).value_or(0) == 40.0 * 41 * 81 / 6);
  BOOST_TEST(CGAL::exact(region.area) == Rational(40 * 41 * 81 / 6));
}

BOOST_AUTO_TEST_CASE(one_polygon_has_its_shoelace_area) {
  std::mt19937 random(1980);
  for (int trial = 0; trial < 50; ++trial) {
    const Rational cx = random_coordinate(random, 100), cy = random_coordinate(random, 100);
    const Ring2 ring = canonical_ring(random_quadrilateral(random, cx, cy));
    const Rational expected = shoelace(ring);
    const Region2 region = canonical_region({Polygon2{ring, {}}});
    const CGAL::Interval_nt<false> interval = region.area.approx();
    BOOST_TEST(Rational(interval.inf()) <= expected);
    BOOST_TEST(expected <= Rational(interval.sup()));
    if (const std::optional<double> value = truncated_to_double(region.area))
      BOOST_TEST(*value == expected.get_d());
    BOOST_TEST(CGAL::exact(region.area) == expected);
  }
}

BOOST_AUTO_TEST_CASE(area_sign_is_the_sign_of_the_shoelace_area) {
  // Rings of 3 to 6 corners on a lattice of thirds (not doubles: the intervals are not
  // points) in a 4 x 4 square, so that many are flat or cancel to a zero area, which the
  // intervals cannot decide; and the same rings far from the origin.
  std::mt19937 random(1995);
  std::uniform_int_distribution<int> coordinate(0, 12), corners(3, 6);
  int zero = 0, positive = 0, negative = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Rational offset = third(trial % 2 ? 1000003 : 0);
    Ring2 ring;
    for (int k = corners(random); k > 0; --k)
      ring.push_back(point_of(offset + third(coordinate(random)),
                              offset + third(coordinate(random) % (trial % 5 ? 13 : 2))));
    const CGAL::Sign expected = CGAL::sign(shoelace(ring));
    BOOST_TEST(area_sign(ring) == expected);
    zero += expected == CGAL::ZERO;
    positive += expected == CGAL::POSITIVE;
    negative += expected == CGAL::NEGATIVE;
  }
  // All three outcomes are exercised, zero (left to rationals) often.
  BOOST_TEST(zero > 100);
  BOOST_TEST(positive > 300);
  BOOST_TEST(negative > 300);
}

// canonical_region sorts polygons by their outer rings, lexicographically by corners (each
// corner by x, then y): the order compared with one written here, on shuffled polygons whose
// first corners share x exactly (a coarse grid, thirds), or differ by 10^-30 (x intervals that
// overlap), with the same first corner (the next corners decide), and with holes.
BOOST_AUTO_TEST_CASE(polygons_are_sorted_by_their_outer_rings) {
  std::mt19937 random(20261208);
  const Rational tiny(1, mpz_class("1" + std::string(30, '0')));
  const auto corner_less = [](const Point2& a, const Point2& b) {
    const RationalPoint2 &p = CGAL::exact(a), &q = CGAL::exact(b);
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  };
  const auto ring_order = [&](const Ring2& a, const Ring2& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), corner_less);
  };
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Polygon2> polygons;
    std::uniform_int_distribution<int> grid(0, 5), kind(0, 3);
    for (int k = 0; k < 200; ++k) {
      Rational x = third(grid(random)), y = third(grid(random));
      if (kind(random) == 0) x += tiny;
      // a right triangle with its smallest corner (x, y) first, counter-clockwise, and legs
      // of random lengths: equal first corners are told apart by the second.
      const Rational a = third(1 + grid(random)), b = third(1 + grid(random));
      Polygon2 polygon{{point_of(x, y), point_of(x + a, y), point_of(x, y + b)}, {}};
      if (kind(random) == 1)
        polygon.holes.push_back({point_of(x + a / 8, y + b / 8), point_of(x + a / 8, y + b / 4),
                                 point_of(x + a / 4, y + b / 8)});
      polygons.push_back(std::move(polygon));
    }
    std::vector<Polygon2> expected = polygons;
    std::stable_sort(expected.begin(), expected.end(), [&](const Polygon2& a, const Polygon2& b) {
      return ring_order(a.outer, b.outer);
    });
    std::shuffle(polygons.begin(), polygons.end(), random);
    const Region2 region = canonical_region(polygons);
    BOOST_TEST_REQUIRE(region.polygons.size() == expected.size());
    std::size_t out_of_order = 0;
    for (std::size_t k = 0; k < expected.size(); ++k)
      out_of_order += ring_order(region.polygons[k].outer, expected[k].outer) ||
                      ring_order(expected[k].outer, region.polygons[k].outer);
    BOOST_TEST(out_of_order == 0u);
    for (std::size_t k = 1; k < region.polygons.size(); ++k)
      BOOST_TEST(!ring_order(region.polygons[k].outer, region.polygons[k - 1].outer));
  }
}

BOOST_AUTO_TEST_SUITE_END()
