// The overlay of many regions (region_overlay.h) against counting: at random rational
// points, the part of the window that holds the point must carry the number of regions
// that hold it (each tested on its own, exactly), and the parts must tile the window; for
// regions with integer corners and with rational ones.

#include <boost/test/unit_test.hpp>

#include <random>

#include "penumbra/geometry/exact.h"
#include "penumbra/shadow/region_overlay.h"
#include "region_set.h"
#include "shadow_support.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

Ring2 square(int x0, int y0, int x1, int y1) {
  return {Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)};
}

// returns a random triangle with corners made by corner(random), counter-clockwise.
template <typename Corner>
Ring2 random_triangle(std::mt19937& random, const Corner& corner) {
  for (;;) {
    Ring2 ring;
    for (int k = 0; k < 3; ++k) ring.push_back(corner(random));
    const auto turn = CGAL::orientation(ring[0], ring[1], ring[2]);
    if (turn == CGAL::COLLINEAR) continue;
    if (turn == CGAL::CLOCKWISE) std::swap(ring[1], ring[2]);
    return ring;
  }
}

// integer corners in [0, 12]^2 (lazy points made from doubles): shared edges, shared
// vertices and collinear overlaps are frequent.
Point2 integer_corner(std::mt19937& random) {
  std::uniform_int_distribution<int> coordinate(0, 12);
  const int x = coordinate(random);
  return Point2(x, coordinate(random));
}

// corners p/q in [0, 12]^2 with q up to 97, their exact values stored (as the corners of
// shadow polygons are): edges crossing at points of large denominators.
Point2 rational_corner(std::mt19937& random) {
  std::uniform_int_distribution<int> denominator(1, 97);
  const auto coordinate = [&] {
    const int q = denominator(random);
    Rational x(std::uniform_int_distribution<int>(0, 12 * q)(random), q);
    x.canonicalize();
    return x;
  };
  Rational x = coordinate();
  return from_exact<Point2>(RationalPoint2(x, coordinate()));
}

// checks coverage against counting at random points, for regions that are unions of one to
// three random triangles made by corner, less the window's hole.
template <typename Corner>
void check_counts(std::uint32_t seed, const Corner& corner) {
  // The window: [0, 12]^2 with the hole [5, 7]^2 (clockwise).
  Ring2 hole = square(5, 5, 7, 7);
  std::reverse(hole.begin(), hole.end());
  const Polygon2 window{canonical_ring(square(0, 0, 12, 12)), {canonical_ring(hole)}};
  const Region2 whole = canonical_region({window});
  std::mt19937 random(seed);
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Region2> regions;
    const int count = 1 + trial % 7;
    for (int k = 0; k < count; ++k) {
      std::vector<Ring2> triangles;
      for (int t = 0; t < 1 + k % 3; ++t) triangles.push_back(random_triangle(random, corner));
      regions.push_back(detail::unite_minus(triangles, {square(5, 5, 7, 7)}));
    }
    std::vector<const Region2*> pointers;
    for (const Region2& region : regions) pointers.push_back(&region);
    const std::size_t base = trial % 3;
    const std::vector<Coverage> parts = coverage(window, pointers, base);

    // The parts tile the window: their areas add up to its area exactly.
    Exact total = 0;
    for (const Coverage& part : parts) total += part.region.area;
    BOOST_TEST((total == whole.area));
    for (std::size_t k = 1; k < parts.size(); ++k) BOOST_TEST(parts[k - 1].count < parts[k].count);

    std::size_t compared = 0;
    for (int s = 0; s < 300; ++s) {
      const Point2 p(Exact(std::uniform_int_distribution<int>(1, 12 * 997 - 1)(random)) / 997,
                     Exact(std::uniform_int_distribution<int>(1, 12 * 997 - 1)(random)) / 997);
      if (locate(whole, p) != Where::inside) continue;
      const std::optional<std::size_t> holding = regions_holding(regions, p);
      if (!holding) continue;
      check_one_part_holds(parts, p, base + *holding);
      ++compared;
    }
    BOOST_TEST(compared > 200u);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(region_overlay)

BOOST_AUTO_TEST_CASE(each_part_carries_the_number_of_regions_over_it) {
  check_counts(20261202, integer_corner);
}

// The overlay computes the points where edges cross from integer lines through the edges'
// ends (region_overlay.cpp, exact_vertices): with rational corners every such point has a
// large denominator, and one wrong digit breaks the exact tiling or a count.
BOOST_AUTO_TEST_CASE(parts_are_exact_where_edges_of_rational_corners_cross) {
  check_counts(20261205, rational_corner);
}

BOOST_AUTO_TEST_CASE(no_regions_leave_the_window_whole_with_the_base_count) {
  const Polygon2 window{canonical_ring(square(0, 0, 3, 2)), {}};
  const std::vector<Coverage> parts = coverage(window, {}, 5);
  BOOST_TEST_REQUIRE(parts.size() == 1u);
  BOOST_TEST(parts.front().count == 5u);
  BOOST_TEST((parts.front().region == canonical_region({window})));
}

// Two triangles touching at their leftmost corner (3, 11/2): the window's part around them
// is bounded by one ring that passes that corner twice, going round each triangle
// clockwise. Its turn at that corner, where the ring goes from one triangle to the other,
// is counter-clockwise: an orientation test there took it for the part's outer boundary,
// and the window's own boundary was lost. The areas, derived by hand: each triangle
// 1/2 |det| = 1/2 |1 * 3/2 - 1 * 0| = 1/2 |1 * 1/2 + 1 * 1| = 3/4; the window 64.
BOOST_AUTO_TEST_CASE(a_ring_touching_itself_at_its_smallest_corner_is_a_hole) {
  const Polygon2 window{canonical_ring(square(0, 0, 8, 8)), {}};
  const Exact triangle = Exact(3) / 4;
  const Point2 touch(3, Exact(11) / 2);
  const Region2 up = canonical_region(
      {Polygon2{canonical_ring({touch, Point2(4, Exact(13) / 2), Point2(3, 7)}), {}}});
  const Region2 down = canonical_region(
      {Polygon2{canonical_ring({touch, Point2(4, Exact(9) / 2), Point2(4, 6)}), {}}});
  BOOST_TEST_REQUIRE((up.area == triangle));
  BOOST_TEST_REQUIRE((down.area == triangle));
  for (const auto& regions : {std::vector<const Region2*>{&up, &down}, {&down, &up}}) {
    const std::vector<Coverage> parts = coverage(window, regions);
    BOOST_TEST_REQUIRE(parts.size() == 2u);
    BOOST_TEST((parts[0].region.area == Exact(64) - 2 * triangle));
    BOOST_TEST_REQUIRE(parts[0].region.polygons.size() == 1u);
    BOOST_TEST((parts[0].region.polygons[0].outer == window.outer));
    BOOST_TEST((parts[1].region.area == 2 * triangle));
  }
}

BOOST_AUTO_TEST_CASE(an_intersection_holds_the_points_both_regions_hold) {
  // Unions of random triangles (one less a hole) intersected pairwise: at random rational
  // points, inside the intersection exactly when strictly inside both; its area is that of
  // the part of the window [0, 12]^2 that both cover in the overlay of the two (coverage),
  // and the same either way round.
  const Polygon2 window{canonical_ring(square(0, 0, 12, 12)), {}};
  std::mt19937 random(23);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Ring2> first, second;
    for (int t = 0; t < 1 + trial % 3; ++t)
      first.push_back(random_triangle(random, integer_corner));
    for (int t = 0; t < 1 + (trial / 3) % 3; ++t)
      second.push_back(random_triangle(random, integer_corner));
    const Region2 a = detail::unite_minus(first, {square(5, 5, 7, 7)});
    const Region2 b = detail::unite_minus(second);
    const Region2 both = intersection(a, b);
    BOOST_TEST((both.area == intersection(b, a).area));
    Exact covered_twice = 0;
    for (const Coverage& part : coverage(window, {&a, &b}))
      if (part.count == 2) covered_twice = part.region.area;
    BOOST_TEST((both.area == covered_twice));
    std::size_t compared = 0;
    for (int s = 0; s < 300; ++s) {
      const Point2 p(Exact(std::uniform_int_distribution<int>(1, 12 * 997 - 1)(random)) / 997,
                     Exact(std::uniform_int_distribution<int>(1, 12 * 997 - 1)(random)) / 997);
      const Where in_a = locate(a, p), in_b = locate(b, p);
      if (in_a == Where::boundary || in_b == Where::boundary) continue;
      const bool expected = in_a == Where::inside && in_b == Where::inside;
      BOOST_TEST((locate(both, p) == Where::inside) == expected);
      ++compared;
    }
    BOOST_TEST(compared > 250u);
  }
}

BOOST_AUTO_TEST_SUITE_END()
