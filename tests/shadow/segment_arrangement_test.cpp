// The pairwise arrangement of segments (src/shadow/segment_arrangement.h) against two
// independent computations: CGAL's sweep (CGAL::insert into an Arrangement_2) must find the
// same numbers of vertices, edges and faces; and at random rational points, the region
// read back for a count must hold exactly the points that this many of the overlaid
// regions hold, each region tested on its own. Regions are unions of random triangles and
// squares less holes, with corners on a half-unit grid (shared corners, shared and
// overlapping edges, corners on edges, touching components everywhere), at multiples of
// 1/97 (crossings of large denominators, components inside holes), or on the grid in small
// cells (components apart, placed by rays that meet other components' corners).

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <cstdlib>
#include <random>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include "penumbra/geometry/exact.h"
#include "region_set.h"
#include "segment_arrangement.h"
#include "shadow_support.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// The window's weight: far above any number of regions, so that a count below it lies
// outside the window.
constexpr long kWindow = 1L << 20;

Ring2 square(int x0, int y0, int x1, int y1) {
  return {Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)};
}

// a corner in [0, 8]^2: on the half-unit grid (mode 0), at a multiple of 1/97 (mode 1), or
// on the half-unit grid in the square [0, 2]^2 at cell (mode 2: small regions, many apart,
// many of their corners at the height of another's).
Point2 corner(std::mt19937& random, int mode, const Point2& cell) {
  if (mode != 1) {
    std::uniform_int_distribution<int> grid(0, mode == 0 ? 16 : 4);
    const int x = grid(random);
    return Point2(cell.x() + x / 2.0, cell.y() + grid(random) / 2.0);
  }
  std::uniform_int_distribution<int> fine(0, 8 * 97);
  Rational x(fine(random), 97), y(fine(random), 97);
  x.canonicalize();  // GMP's operands must be in lowest terms
  y.canonicalize();
  return from_exact<Point2>(RationalPoint2(x, y));
}

// a region: the union of one to three random triangles, less a random square half the
// time (holes, and pieces touching at corners).
Region2 random_region(std::mt19937& random, int mode) {
  std::vector<Ring2> triangles;
  const int count = std::uniform_int_distribution<int>(1, 3)(random);
  std::uniform_int_distribution<int> at(0, 6);
  const Point2 cell = mode == 2 ? Point2(at(random), at(random)) : Point2(0, 0);
  while (static_cast<int>(triangles.size()) < count) {
    Ring2 ring{corner(random, mode, cell), corner(random, mode, cell), corner(random, mode, cell)};
    const CGAL::Orientation turn = CGAL::orientation(ring[0], ring[1], ring[2]);
    if (turn == CGAL::COLLINEAR) continue;
    if (turn == CGAL::CLOCKWISE) std::swap(ring[1], ring[2]);
    triangles.push_back(std::move(ring));
  }
  std::vector<Ring2> subtract;
  if (mode != 2 && std::uniform_int_distribution<int>(0, 1)(random) == 1) {
    const int x = at(random), y = at(random);
    subtract.push_back(square(x, y, x + 2, y + 2));
  }
  return detail::unite_minus(triangles, subtract);
}

std::vector<detail::LayerSegment> segments_of(const Polygon2& window,
                                              const std::vector<Region2>& regions) {
  std::vector<detail::LayerSegment> segments;
  const auto add = [&](const Ring2& ring, long weight) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      segments.push_back({ring[i], ring[(i + 1) % ring.size()], weight});
  };
  add(window.outer, kWindow);
  for (const Region2& region : regions)
    for (const Polygon2& polygon : region.polygons) {
      add(polygon.outer, 1);
      for (const Ring2& hole : polygon.holes) add(hole, 1);
    }
  return segments;
}

// checks the arrangement of the window's and the regions' segments against CGAL's sweep
// and against counting at random points.
void check(const Polygon2& window, const std::vector<Region2>& regions, std::mt19937& random) {
  const std::vector<detail::LayerSegment> segments = segments_of(window, regions);
  const detail::SegmentArrangement arrangement = detail::arrange(segments);

  // The same map as CGAL's sweep: vertices, edges and faces (the unbounded one included).
  using Arrangement = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<Kernel>>;
  Arrangement reference;
  std::vector<Arrangement::X_monotone_curve_2> curves;
  for (const detail::LayerSegment& s : segments) curves.emplace_back(s.a, s.b);
  CGAL::insert(reference, curves.begin(), curves.end());
  BOOST_TEST(arrangement.points.size() == reference.number_of_vertices());
  BOOST_TEST(arrangement.origin.size() / 2 == reference.number_of_edges());
  BOOST_TEST(arrangement.faces == reference.number_of_faces());

  // Crossing an edge from the left of 2e to its right takes its left count off, whichever
  // path the counts spread along.
  std::size_t inconsistent = 0;
  for (std::size_t h = 0; h < arrangement.origin.size(); h += 2)
    inconsistent += arrangement.count[arrangement.face[h + 1]] !=
                    arrangement.count[arrangement.face[h]] - arrangement.left[h / 2];
  BOOST_TEST(inconsistent == 0u);

  // Each count's region, read back, holds the points that many regions hold; together they
  // tile the window.
  std::vector<Coverage> parts;
  for (detail::KeyPolygons& entry : detail::polygons_by_count(
           arrangement, [](long count) { return count >= kWindow ? count - kWindow : -1; })) {
    // The enclosure of the area, from the vertices, holds the rings' exact shoelace area.
    const Region2 region = canonical_region(entry.polygons);
    const Rational scaled = exact_value(region.area) * Rational(mpz_class(1) << kEnclosureBits);
    BOOST_TEST(Rational(entry.area.lower) <= scaled);
    BOOST_TEST(scaled <= Rational(entry.area.upper));
    parts.push_back({static_cast<std::size_t>(entry.key), region});
  }
  // The same with the faces of the window alone keyed as the unbounded face: those joined to
  // it are dropped, and the areas of the rest are still enclosed.
  for (const detail::KeyPolygons& entry : detail::polygons_by_count(
           arrangement, [](long count) { return count == 0 ? 0 : count - kWindow; })) {
    const Region2 region = canonical_region(entry.polygons);
    const Rational scaled = exact_value(region.area) * Rational(mpz_class(1) << kEnclosureBits);
    BOOST_TEST(Rational(entry.area.lower) <= scaled);
    BOOST_TEST(scaled <= Rational(entry.area.upper));
  }
  Exact total = 0;
  for (const Coverage& part : parts) total += part.region.area;
  BOOST_TEST((total == canonical_region({window}).area));
  std::size_t compared = 0;
  for (int s = 0; s < 100; ++s) {
    const Point2 p(Exact(std::uniform_int_distribution<int>(1, 8 * 991 - 1)(random)) / 991,
                   Exact(std::uniform_int_distribution<int>(1, 8 * 991 - 1)(random)) / 991);
    const std::optional<std::size_t> holding = regions_holding(regions, p);
    if (!holding) continue;
    check_one_part_holds(parts, p, *holding);
    ++compared;
  }
  BOOST_TEST(compared > 80u);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(segment_arrangement)

BOOST_AUTO_TEST_CASE(random_regions_give_cgals_map_and_the_counted_regions) {
  const Polygon2 window{canonical_ring(square(0, 0, 8, 8)), {}};
  std::mt19937 random(20261207);
  for (int trial = 0; trial < 240; ++trial) {
    const int mode = trial % 3;
    std::vector<Region2> regions;
    const int count = std::uniform_int_distribution<int>(1, 10)(random);
    while (static_cast<int>(regions.size()) < count)
      if (Region2 region = random_region(random, mode); !region.empty())
        regions.push_back(std::move(region));
    BOOST_TEST_CONTEXT("trial " << trial) {
      check(window, regions, random);
    }
  }
}

// Components apart, one inside another's hole: each is placed by a ray to its left, and the
// counts derived by hand. Window [0, 10]^2 (count 0); a ring [2, 8]^2 less [3, 7]^2 (count 1,
// area 36 - 16 = 20); an island [4, 6]^2 in its hole (count 1, area 4); a square [8, 9] x
// [0, 1] below and right of the ring, apart from it (count 1, area 1). Count 0 is the rest:
// 100 - 25.
BOOST_AUTO_TEST_CASE(an_island_in_a_hole_has_the_count_derived_by_hand) {
  const Polygon2 window{canonical_ring(square(0, 0, 10, 10)), {}};
  Ring2 hole = square(3, 3, 7, 7);
  std::reverse(hole.begin(), hole.end());
  const std::vector<Region2> regions{
      canonical_region({Polygon2{canonical_ring(square(2, 2, 8, 8)), {canonical_ring(hole)}}}),
      canonical_region({Polygon2{canonical_ring(square(4, 4, 6, 6)), {}}}),
      canonical_region({Polygon2{canonical_ring(square(8, 0, 9, 1)), {}}})};
  const detail::SegmentArrangement arrangement = detail::arrange(segments_of(window, regions));
  // Faces: the unbounded one, the window less the rest, the ring, the hole less the island,
  // the island, the small square.
  BOOST_TEST(arrangement.faces == 6u);
  std::map<long, Exact> area;
  for (detail::KeyPolygons& entry : detail::polygons_by_count(
           arrangement, [](long count) { return count >= kWindow ? count - kWindow : -1; }))
    area[entry.key] = canonical_region(std::move(entry.polygons), entry.area).area;
  BOOST_TEST_REQUIRE(area.size() == 2u);
  BOOST_TEST((area[1] == Exact(20 + 4 + 1)));
  BOOST_TEST((area[0] == Exact(100 - 25)));
  // Keys that put the faces of the window alone with the unbounded face: those around the
  // ring join it and are dropped (a polygon with no outer boundary, whose rings' areas are
  // taken off again), and the pocket in the ring's hole is kept. Its area, 16 - 4, is
  // enclosed exactly: the corners are integers.
  const std::vector<detail::KeyPolygons> merged = detail::polygons_by_count(
      arrangement, [](long count) { return count == 0 || count == kWindow ? 0 : -1; });
  BOOST_TEST_REQUIRE(merged.size() == 1u);
  BOOST_TEST((canonical_region(merged[0].polygons).area == Exact(16 - 4)));
  BOOST_TEST(merged[0].area.lower == mpz_class(16 - 4) << kEnclosureBits);
  BOOST_TEST(merged[0].area.upper == mpz_class(16 - 4) << kEnclosureBits);
  std::mt19937 random(7);
  check(window, regions, random);
}

// Traced from outside, the faces counting one ring or more are the union a polygon set gives,
// written alike where it touches itself (parts touching at a corner are one polygon, a hole
// touching the outer boundary is a hole): against CGAL's Polygon_set_2 (unite_minus), exactly,
// on random triangles with corners on a half-unit grid, in small cells or at multiples of
// 1/97.
BOOST_AUTO_TEST_CASE(traced_from_outside_a_union_is_the_polygon_sets) {
  std::mt19937 random(20261208);
  std::size_t pinched = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int mode = trial % 3;
    std::uniform_int_distribution<int> at(0, 6);
    const Point2 cell = mode == 2 ? Point2(at(random), at(random)) : Point2(0, 0);
    std::vector<Ring2> triangles;
    const int count = std::uniform_int_distribution<int>(2, 8)(random);
    while (static_cast<int>(triangles.size()) < count) {
      Ring2 ring{corner(random, mode, cell), corner(random, mode, cell),
                 corner(random, mode, cell)};
      const CGAL::Orientation turn = CGAL::orientation(ring[0], ring[1], ring[2]);
      if (turn == CGAL::COLLINEAR) continue;
      if (turn == CGAL::CLOCKWISE) std::swap(ring[1], ring[2]);
      triangles.push_back(std::move(ring));
    }
    std::vector<detail::LayerSegment> segments;
    for (const Ring2& ring : triangles)
      for (std::size_t i = 0; i < ring.size(); ++i)
        segments.push_back({ring[i], ring[(i + 1) % ring.size()], 1});
    std::vector<Polygon2> polygons;
    for (detail::KeyPolygons& united : detail::polygons_by_count(
             detail::arrange(segments), [](long c) { return c > 0 ? 0L : -1L; },
             detail::TraceSide::outside))
      polygons = std::move(united.polygons);
    const Region2 mine = canonical_region(std::move(polygons));
    const Region2 reference = detail::unite_minus(triangles);
    BOOST_TEST_CONTEXT("trial " << trial) {
      BOOST_TEST((mine == reference));
    }
    // Count the unions that touch themselves at a point (a ring passing a corner twice).
    for (const Polygon2& polygon : reference.polygons) {
      std::vector<Ring2> rings{polygon.outer};
      rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
      for (const Ring2& ring : rings)
        for (std::size_t i = 0; i < ring.size(); ++i)
          for (std::size_t j = i + 1; j < ring.size(); ++j) pinched += ring[i] == ring[j];
    }
  }
  BOOST_TEST(pinched >= 15u);  // 18 with this seed
}

BOOST_AUTO_TEST_SUITE_END()
