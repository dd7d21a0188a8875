// The interval filter of the blocked interval (src/shadow/blocked_interval_filter.h) against
// the exact clipping (blocked_interval.h), on what real models give the joint umbra: a wall
// cut into touching pieces that share faces and edges, under a tube parallel to it or
// askew, seen from rational points of the ground (fixed seed). Wherever the filter
// certifies a result it must be the exact one: the same kind, enclosures that hold the
// exact ends, and the same edges; and the exact end is then the named edge's parameter at
// the point (edge_parameter), which is how the sweep evaluates the ends the filter names.
// With the edges' parameters the filter must also certify most points: a flat panel gives a
// clipped polygon with two vertices on one edge, the same point, which intervals alone
// cannot tell apart.

#include <boost/test/unit_test.hpp>

#include <CGAL/FPU.h>

#include <random>

#include "blocked_interval.h"
#include "blocked_interval_filter.h"
#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/exact.h"

using namespace penumbra;
using detail::BlockedInterval;

namespace {

// a box [x0, x1] x [y0, y1] x [z0, z1]
ConvexPolyhedron box(const Exact& x0, const Exact& x1, const Exact& y0, const Exact& y1,
                     const Exact& z0, const Exact& z1) {
  std::vector<Point3> corners;
  for (const Exact& x : {x0, x1})
    for (const Exact& y : {y0, y1})
      for (const Exact& z : {z0, z1}) corners.emplace_back(x, y, z);
  return ConvexPolyhedron::hull(corners);
}

// num / den in lowest terms (GMP's rationals must be canonical)
Rational fraction(int num, int den) {
  Rational r(num, den);
  r.canonicalize();
  return r;
}

bool holds(const Interval& enclosure, const Rational& value) {
  return Rational(enclosure.inf()) <= value && value <= Rational(enclosure.sup());
}

struct Counts {
  int checked = 0, certified = 0, certified_plain = 0;
};

// checks every piece at every point; returns how many the filter certified with and without
// the edges' parameters.
Counts check_wall(const std::vector<ConvexPolyhedron>& pieces, const Point3& q1, const Point3& q2,
                  const std::vector<RationalPoint3>& points) {
  const RationalPoint3 r1 = exact_value(q1), r2 = exact_value(q2);
  Counts counts;
  for (const ConvexPolyhedron& piece : pieces) {
    const detail::RationalSolid solid = detail::rational_solid(piece);
    const detail::IntervalSolid plain = detail::interval_solid(solid);
    detail::IntervalSolid with_edges = plain;
    detail::enclose_edge_parameters(with_edges, detail::edge_parameters(solid, r1, r2));
    for (const RationalPoint3& p : points) {
      const BlockedInterval exact = detail::blocked_interval(solid, p, r1, r2);
      std::optional<detail::BlockedBounds> filtered, filtered_plain;
      {
        CGAL::Protect_FPU_rounding<true> upward;
        const IntervalPoint at = detail::interval_point(p), i1 = detail::interval_point(r1),
                            i2 = detail::interval_point(r2);
        filtered = detail::blocked_bounds(with_edges, at, i1, i2);
        filtered_plain = detail::blocked_bounds(plain, at, i1, i2);
      }
      if (exact.kind != BlockedInterval::Kind::interval) {
        if (filtered) BOOST_TEST((filtered->kind == exact.kind));
        continue;
      }
      ++counts.checked;
      counts.certified_plain += filtered_plain.has_value();
      if (!filtered) continue;
      ++counts.certified;
      BOOST_TEST((filtered->kind == exact.kind));
      BOOST_TEST(holds(filtered->low, exact.low));
      BOOST_TEST(holds(filtered->high, exact.high));
      BOOST_TEST(filtered->low_edge == exact.low_edge);
      BOOST_TEST(filtered->high_edge == exact.high_edge);
      BOOST_TEST(filtered->low_clamped == (exact.low == 0));
      BOOST_TEST(filtered->high_clamped == (exact.high == 1));
      // the named edges' parameters at p are the exact ends
      for (const auto& [edge, end] :
           {std::pair{exact.low_edge, exact.low}, std::pair{exact.high_edge, exact.high}}) {
        if (edge < 0) continue;
        const auto& e = solid.edges[edge];
        const detail::EdgeParameter t =
            detail::edge_parameter(solid.vertices[e[0]], solid.vertices[e[1]], r1, r2);
        const RationalVector3 o = p - CGAL::ORIGIN;
        const Rational value = (t.gn * o + t.hn) / (t.gd * o + t.hd);
        BOOST_TEST(value == end);
      }
    }
  }
  return counts;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(blocked_bounds)

BOOST_AUTO_TEST_CASE(certifies_only_the_exact_interval_and_most_of_a_wall_of_touching_pieces) {
  std::mt19937 random(20261206);
  std::uniform_int_distribution<int> cut(1, 7), coordinate(-4000, 4000);
  int checked = 0, certified = 0, certified_plain = 0;
  for (int scene = 0; scene < 6; ++scene) {
    // a wall 3 m long, 0.3 m thick, from 1 m to 3.5 m up, cut across x into touching pieces;
    // a facade of flat panels in the plane y = 1 beside it, cut alike (a flat polygon's two
    // faces share a plane: its clipped triangle is a segment, met twice by each edge plane)
    std::vector<ConvexPolyhedron> pieces;
    for (Exact x = 0; x < 3;) {
      const Exact next = std::min(Exact(3), x + Exact(cut(random)) / 10);
      pieces.push_back(box(x, next, 0, Exact(3) / 10, 1, Exact(7) / 2));
      x = next;
    }
    for (Exact x = 0; x < 3;) {
      const Exact next = std::min(Exact(3), x + Exact(cut(random)) / 10);
      pieces.push_back(ConvexPolyhedron::flat_polygon({Point3(x, 1, 1), Point3(next, 1, 1),
                                                       Point3(next, 1, Exact(7) / 2),
                                                       Point3(x, 1, Exact(7) / 2)}));
      x = next;
    }
    // the tube parallel to the wall (as over the FZK house), then askew
    const bool parallel = scene % 2 == 0;
    const Point3 q1(-1, -2, 6),
        q2(parallel ? Exact(4) : Exact(3), parallel ? -2 : -1, parallel ? Exact(6) : Exact(13) / 2);
    std::vector<RationalPoint3> points;
    // (every fifth point in the plane of the wall's faces or of the panels: there two
    // vertices on different edges lie on one ray from the point)
    const Rational planes[3] = {0, fraction(3, 10), 1};
    for (int k = 0; k < 300; ++k) {
      const Rational x = fraction(coordinate(random), 1000);
      const Rational y = fraction(coordinate(random), 997);
      points.emplace_back(x, k % 5 == 0 ? planes[k % 3] : y, 0);
    }
    const Counts counts = check_wall(pieces, q1, q2, points);
    checked += counts.checked;
    certified += counts.certified;
    certified_plain += counts.certified_plain;
  }
  BOOST_TEST_MESSAGE("blocked intervals " << checked << ", certified " << certified
                                          << " (without the edges' parameters " << certified_plain
                                          << ")");
  BOOST_TEST(checked > 1000);
  BOOST_TEST(certified >= certified_plain);
  BOOST_TEST(certified * 10 >= checked * 9);
}

BOOST_AUTO_TEST_SUITE_END()
