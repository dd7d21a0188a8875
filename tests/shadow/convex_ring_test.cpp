// The interval filters of the joint-umbra sweep (src/shadow/convex_ring.h, pencil.h)
// against the exact answers they stand in front of: CGAL's exact bounded_side for points
// in convex rings, the sign of an affine function evaluated in rationals, Taylor's shift
// against evaluation at c + t, and enclosures that must hold the exact value. The points
// include those the intervals cannot decide (on edges and lines, 1e-30 away from them).

#include <boost/test/unit_test.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "convex_ring.h"
#include "pencil.h"
#include "rational_enclosure.h"

using namespace penumbra;
using detail::Affine2;
using detail::ConvexRing;
using detail::FilteredAffine;
using detail::Poly;
using detail::Probe;
using detail::RationalVector2;

namespace {

// a convex counter-clockwise hexagon at full-double coordinates (cos and sin of angles).
std::vector<RationalPoint2> hexagon(double cx, double cy, double radius, double turn) {
  std::vector<RationalPoint2> ring;
  for (int k = 0; k < 6; ++k) {
    const double angle = turn + k * M_PI / 3;
    ring.emplace_back(cx + radius * std::cos(angle), cy + radius * std::sin(angle));
  }
  return ring;
}

// a / b in lowest terms (gmpxx's two-argument constructor does not reduce).
Rational ratio(long a, long b) {
  return Rational(a) / Rational(b);
}

bool encloses(const Interval& box, const Rational& x) {
  return Rational(box.inf()) <= x && x <= Rational(box.sup());
}

// random rational points: uniform in a box, vertices, points on edges, and points a hair
// (1e-30) off an edge on either side.
std::vector<RationalPoint2> probes(const std::vector<RationalPoint2>& ring, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-12, 12);
  std::uniform_int_distribution<int> fraction(1, 999);
  std::vector<RationalPoint2> points;
  for (int k = 0; k < 300; ++k) points.emplace_back(coordinate(rng), coordinate(rng));
  const Rational hair = Rational(1) / Rational(mpz_class("1000000000000000000000000000000"));
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const RationalPoint2& a = ring[k];
    const RationalPoint2& b = ring[(k + 1) % ring.size()];
    points.push_back(a);
    const Rational t = ratio(fraction(rng), 1000);
    const RationalPoint2 on = a + t * (b - a);
    points.push_back(on);
    const RationalVector2 normal(b.y() - a.y(), a.x() - b.x());  // points outward
    points.push_back(on + hair * normal);
    points.push_back(on - hair * normal);
  }
  return points;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(interval_filters)

BOOST_AUTO_TEST_CASE(ring_membership_agrees_with_exact_bounded_side) {
  std::mt19937 rng(1729);
  int undecided = 0, checked = 0, boundary = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::uniform_real_distribution<double> centre(-4, 4), radius(1, 8), turn(0, 1);
    const auto points = hexagon(centre(rng), centre(rng), radius(rng), turn(rng));
    const ConvexRing ring(points);
    for (const RationalPoint2& p : probes(points, rng)) {
      const CGAL::Bounded_side side =
          CGAL::bounded_side_2(points.begin(), points.end(), p, ExactKernel());
      const bool exact = side != CGAL::ON_UNBOUNDED_SIDE;
      BOOST_TEST(ring.contains(p) == exact);
      BOOST_TEST(ring.strictly_contains(Probe(p)) == (side == CGAL::ON_BOUNDED_SIDE));
      boundary += side == CGAL::ON_BOUNDARY;
      const Probe probe(p);
      CGAL::Protect_FPU_rounding<true> upward;
      const auto maybe = ring.maybe_contains(probe.at);
      if (maybe)
        BOOST_TEST(*maybe == exact);
      else
        ++undecided;
      ++checked;
    }
  }
  // the points on and a hair off the edges are the ones intervals cannot settle
  BOOST_TEST(undecided > 0);
  BOOST_TEST(undecided < checked / 2);
  BOOST_TEST(boundary >= 240);  // (vertices and points on edges: strictly_contains says no)
  BOOST_TEST(!ConvexRing({{0, 0}, {1, 1}}).contains(RationalPoint2(0, 0)));  // fewer than 3
}

BOOST_AUTO_TEST_CASE(affine_sign_agrees_with_rationals) {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> coefficient(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    const Affine2 f{coefficient(rng), coefficient(rng), coefficient(rng)};
    const FilteredAffine filtered(f);
    // points on the line (x chosen, y solved exactly) and off it
    const Rational x = coefficient(rng);
    const RationalPoint2 on(x, -(f.d * x + f.f) / f.e);
    const RationalPoint2 off(coefficient(rng), coefficient(rng));
    for (const RationalPoint2& p : {on, off})
      BOOST_TEST(filtered.sign(Probe(p)) == CGAL::sign(f(p)));
    BOOST_TEST(filtered.sign(Probe(on)) == CGAL::ZERO);
  }
}

BOOST_AUTO_TEST_CASE(taylor_shift_is_evaluation_at_c_plus_t) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> integer(-50, 50);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Rational> c;
    for (int k = 0, n = 1 + trial % 4; k < n; ++k) c.push_back(ratio(integer(rng), 7));
    const Poly p(c);
    const Rational shift = ratio(integer(rng) * 1000003L, 13), t = ratio(integer(rng), 11);
    BOOST_TEST(p.shifted(shift)(t) == p(shift + t));
  }
}

BOOST_AUTO_TEST_CASE(enclosures_hold_the_exact_values) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> integer(-40, 40);
  const auto pencil = detail::Pencil::cone(RationalPoint2(ratio(1, 3), ratio(-2, 7)),
                                           RationalVector2(1, 0), RationalVector2(0, 1));
  for (int trial = 0; trial < 100; ++trial) {
    const detail::PencilCurve curve{Poly({ratio(integer(rng), 3), ratio(integer(rng), 5)}),
                                    Poly({ratio(1 + trial, 7), ratio(integer(rng), 9)})};
    const Rational s = ratio(trial + 1, 101);
    const Rational den = curve.den(s);
    CGAL::Protect_FPU_rounding<true> upward;
    const Interval enclosed_s(CGAL::to_interval(s));
    const auto r = detail::IntervalCurve(curve).r(enclosed_s);
    if (CGAL::is_zero(den)) {
      BOOST_TEST(!r);
      continue;
    }
    BOOST_REQUIRE(r);
    const Rational exact_r = curve.r(s);
    BOOST_TEST(encloses(*r, exact_r));
    const auto at = detail::interval_point(pencil, enclosed_s, *r);
    const RationalPoint2 exact_point = pencil.point(s, exact_r);
    BOOST_TEST(encloses(at[0], exact_point.x()));
    BOOST_TEST(encloses(at[1], exact_point.y()));
  }
}

// surely_no_root (pencil.h) on polynomials built from their roots: k (s - rho_1) ... (s - rho_m)
// (s^2 + c) with c > 0, whose real roots are the rational rho_i and nothing else, given by
// their coefficients' enclosures or by the product of their factors' (product, difference). On
// random closed ranges with rational ends (some ends at a root), it never certifies a range that
// holds a root, and it certifies most of the ranges that hold none (a filter that said nothing
// would fail the count).
BOOST_AUTO_TEST_CASE(no_root_is_certified_only_where_there_is_none) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> integer(-60, 60), positive(1, 40), degree(0, 3);
  int certified = 0, rootless = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Rational> roots;
    std::vector<Poly> factors{Poly({ratio(positive(rng) * (trial % 3 ? 1 : -1), positive(rng))})};
    for (int k = 0, m = degree(rng); k < m; ++k) {
      roots.push_back(ratio(integer(rng), positive(rng)));
      factors.push_back(Poly::linear(-roots.back(), 1));
    }
    if (trial % 2) factors.push_back(Poly({ratio(positive(rng), positive(rng)), 0, 1}));
    Poly p = factors[0];
    for (std::size_t k = 1; k < factors.size(); ++k) p = p * factors[k];
    Rational a = ratio(integer(rng), positive(rng)),
             b = a + ratio(positive(rng), 4 * positive(rng));
    if (!roots.empty() && trial % 5 == 0) a = roots[0];  // a range that ends at a root
    if (!roots.empty() && trial % 7 == 0) b = roots[0];
    if (b < a) std::swap(a, b);
    const bool holds = std::any_of(roots.begin(), roots.end(),
                                   [&](const Rational& r) { return a <= r && r <= b; });
    bool surely, surely_from_factors;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const Interval range(detail::enclosure(a).inf(), detail::enclosure(b).sup());
      surely = detail::surely_no_root(detail::enclosures(p), range);
      // the same polynomial from its factors' enclosures (product), less the zero polynomial
      std::vector<Interval> from_factors = detail::enclosures(factors[0]);
      for (std::size_t k = 1; k < factors.size(); ++k)
        from_factors = detail::product(from_factors, detail::enclosures(factors[k]));
      from_factors = detail::difference(from_factors, std::vector<Interval>(2, Interval(0)));
      surely_from_factors = detail::surely_no_root(from_factors, range);
    }
    if (holds) {
      BOOST_TEST(!surely, "a root in [" << a << ", " << b << "] of trial " << trial);
      BOOST_TEST(!surely_from_factors, "a root in [" << a << ", " << b << "] of trial " << trial);
    }
    certified += surely_from_factors;
    rootless += !holds;
    certified += surely;
  }
  BOOST_TEST(certified > rootless * 3 / 2);  // both forms
  BOOST_TEST_MESSAGE(certified << " of " << 2 * rootless
                               << " rootless ranges certified (both forms)");
}

// short_between (pencil.h): strictly between its bounds, a multiple of a power of two at least
// a quarter of their distance (few significant bits), and nothing between adjacent doubles.
BOOST_AUTO_TEST_CASE(a_short_double_lies_strictly_between) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> value(-1e6, 1e6), exponent(-40, 10);
  int found = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double low = value(rng) * std::pow(2.0, exponent(rng));
    double high;
    switch (trial % 4) {
      case 0:  // adjacent: nothing between
        high = std::nextafter(low, HUGE_VAL);
        break;
      case 1:  // one double between
        high = std::nextafter(std::nextafter(low, HUGE_VAL), HUGE_VAL);
        break;
      default:
        high = low + std::abs(value(rng)) * std::pow(2.0, exponent(rng));
        break;
    }
    const auto r = detail::short_between(low, high);
    if (!(low < high)) {
      BOOST_TEST(!r);
      continue;
    }
    if (trial % 4 == 0) {
      BOOST_TEST(!r);
      continue;
    }
    BOOST_REQUIRE(r);
    ++found;
    BOOST_TEST((low < *r && *r < high));
    // a multiple of 2^(e - 2), where 2^e <= high - low (exact: scaling by a power of two)
    const double unit = std::ldexp(1.0, std::ilogb(high - low) - 2);
    BOOST_TEST(std::floor(*r / unit) == *r / unit);
  }
  BOOST_TEST(found > 14000);
}

// enclosure() (rational_enclosure.h) holds the exact rational and is at most one ulp wide where
// numerator and denominator fit 53 bits (its fast path), under round-to-nearest and under the
// filters' upward rounding alike; larger rationals get CGAL's to_interval. Checked exactly:
// the ends, as rationals, bound the value, and next to CGAL's own enclosure.
BOOST_AUTO_TEST_CASE(the_enclosure_of_a_rational_holds_it_in_any_rounding) {
  std::mt19937_64 rng(101);
  int fast = 0, exact_ends = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int bits = 1 + trial % 70;  // up to 70-bit numerators and denominators
    const auto draw = [&](bool positive) {
      mpz_class z(static_cast<unsigned long>(rng() >> (bits > 64 ? 0 : 64 - std::min(bits, 64))));
      if (bits > 64) z = (z << (bits - 64)) + static_cast<unsigned long>(rng() >> (128 - bits));
      if (positive && z == 0) z = 1;
      if (!positive && (rng() & 1)) z = -z;
      return z;
    };
    Rational x(draw(false), draw(true));
    x.canonicalize();  // the gcd removed
    for (const bool upward : {false, true}) {
      Interval e;
      if (upward) {
        CGAL::Protect_FPU_rounding<true> rounding;
        e = detail::enclosure(x);
      } else {
        e = detail::enclosure(x);
      }
      BOOST_TEST(encloses(e, x));
      const Interval cgal(CGAL::to_interval(x));
      BOOST_TEST(e.inf() >= cgal.inf());  // never wider than CGAL's
      BOOST_TEST(e.sup() <= cgal.sup());
      if (mpz_sizeinbase(x.get_num_mpz_t(), 2) <= 53 &&
          mpz_sizeinbase(x.get_den_mpz_t(), 2) <= 53) {
        ++fast;
        BOOST_TEST(e.sup() <= std::nextafter(e.inf(), HUGE_VAL));
        exact_ends += e.inf() == e.sup();
      }
    }
  }
  BOOST_TEST(fast > 10000);
  BOOST_TEST(exact_ends > 100);  // integers and dyadic quotients: a point interval
  BOOST_TEST_MESSAGE(fast << " enclosures on the fast path, " << exact_ends << " exact");
}

// Pencil::trace of a line (pencil.h), against each line of the pencil met directly: with
// A = P(s, 0) and B = P(s, 1) - A from Pencil::point alone, the line d x + e y + f meets the
// pencil's line s at r = -(line(A)) / (d B_x + e B_y), nowhere when only the denominator is
// zero, and everywhere when both are. The trace must give that r where its den is nonzero,
// den zero where they miss, and the s of whole lines as roots of its rays; num and den share
// no root. Small integers make lines through the centre, along the pencil's direction and
// through the pencil's lines frequent.
BOOST_AUTO_TEST_CASE(a_line_traces_where_it_meets_each_pencil_line) {
  std::mt19937 rng(20261206);
  std::uniform_int_distribution<int> integer(-3, 3);
  const RationalPoint2 x0(ratio(1, 3), ratio(-2, 7));
  const detail::Pencil pencils[] = {
      detail::Pencil::cone(x0, RationalVector2(1, 0), RationalVector2(0, 1)),
      detail::Pencil::cone(x0, RationalVector2(-1, 2), RationalVector2(-3, -1)),
      detail::Pencil::parallel(RationalVector2(2, 1), -3, 3)};
  int curves = 0, rays = 0, misses = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const detail::Pencil& pencil = pencils[trial % 3];
    const auto sample = [&](int k) -> Rational { return ratio(k, 4) + ratio(1, 7 + trial % 5); };
    Affine2 line{integer(rng), integer(rng), integer(rng)};
    if (trial % 4 == 1) {
      // the pencil's own line at a sample s
      const Rational s0 = sample(4 * integer(rng));
      const RationalPoint2 a = pencil.point(s0, 0);
      const RationalVector2 b = pencil.point(s0, 1) - a;
      line = {b.y(), -b.x(), b.x() * a.y() - b.y() * a.x()};
    } else if (trial % 4 == 3) {
      if (pencil.finite())
        line.f = -(line.d * x0.x() + line.e * x0.y());  // through x0
      else
        line = {1, -2, integer(rng)};  // along delta
    }
    if (CGAL::is_zero(line.d) && CGAL::is_zero(line.e)) continue;
    const detail::PencilTrace trace = pencil.trace(line.line());
    if (trace.curve && trace.curve->den.degree() == 1) {
      const auto& den = trace.curve->den.c;
      BOOST_TEST(!CGAL::is_zero(trace.curve->num(-den[0] / den[1])));  // no common factor
    }
    for (int k = -12; k <= 12; ++k) {
      const Rational s = sample(k);
      const RationalPoint2 a = pencil.point(s, 0);
      const RationalVector2 b = pencil.point(s, 1) - a;
      const Rational at_a = line(a), slope = line.d * b.x() + line.e * b.y();
      const bool whole = !trace.rays.zero() && CGAL::is_zero(trace.rays(s));
      if (CGAL::is_zero(slope) && CGAL::is_zero(at_a)) {
        BOOST_TEST(whole, "trial " << trial << " s " << s);
        ++rays;
      } else if (CGAL::is_zero(slope)) {
        BOOST_TEST((!trace.curve || CGAL::is_zero(trace.curve->den(s))));
        ++misses;
      } else if (!whole) {
        const Rational r = -at_a / slope;
        if (!trace.curve) {
          // only a cone's lines through x0 have no curve: r = 0 there
          BOOST_TEST((pencil.finite() && CGAL::is_zero(r)), "trial " << trial);
          continue;
        }
        BOOST_TEST_REQUIRE(!CGAL::is_zero(trace.curve->den(s)));
        BOOST_TEST(trace.curve->r(s) == r, "trial " << trial << " s " << s);
        ++curves;
      }
    }
  }
  BOOST_TEST_MESSAGE(curves << " meetings, " << rays << " whole lines, " << misses << " misses");
  BOOST_TEST(curves > 1000);
  BOOST_TEST(rays > 20);
  BOOST_TEST(misses > 20);
}

BOOST_AUTO_TEST_SUITE_END()
