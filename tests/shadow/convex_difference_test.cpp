// The fast lit-set path of the shadow maps (src/shadow/convex_difference.h): a face minus
// shadow polygons that are strictly apart, walked without an arrangement; and the search
// for overlapping shadows of region_set.h. Checked against
// Polygon_set_2 (region_set.h) on random convex polygons with small integer coordinates,
// so that touching at vertices and along edges, and polygons sharing the window's edges,
// are frequent.

#include <boost/test/unit_test.hpp>
#include <random>

#include "convex_difference.h"
#include "half_plane.h"
#include "region_set.h"
#include "support/heavy.h"

using namespace penumbra;

namespace {

const std::vector<Ring2> windows = {
    {Point2(0, 0), Point2(12, 0), Point2(12, 12), Point2(0, 12)},
    {Point2(0, 0), Point2(12, 0), Point2(0, 12)},
    {Point2(2, 0), Point2(10, 0), Point2(12, 6), Point2(6, 12), Point2(0, 6)}};

// returns one to four convex polygons (by iteration), each window cut by one to four random
// lines through points of the integer grid, other than the whole window.
std::vector<Ring2> random_polygons(std::mt19937& random, const Ring2& window, int iteration) {
  std::uniform_int_distribution<int> coordinate(0, 12);
  std::vector<Ring2> polygons;
  for (int j = 0; j < 1 + iteration % 4; ++j) {
    Ring2 ring = window;
    for (int cut = 0; cut < 1 + (iteration / 4 + j) % 4 && ring.size() >= 3; ++cut) {
      const Point2 p(coordinate(random), coordinate(random)),
          q(coordinate(random), coordinate(random));
      if (p == q) continue;
      const Exact a = q.y() - p.y(), b = p.x() - q.x();
      ring = detail::clip(ring, {a, b, -(a * p.x() + b * p.y())});
    }
    const auto polygon = detail::ring_with_area(ring);
    if (polygon && *polygon != canonical_ring(window)) polygons.push_back(*polygon);
  }
  return polygons;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(convex_difference)

BOOST_AUTO_TEST_CASE(agrees_with_polygon_set_2) {
  std::mt19937 random(7);  // fixed seed
  int tested = 0, several = 0, holes = 0;
  for (int iteration = 0; iteration < penumbra::test::samples(12000); ++iteration) {
    const Ring2& window = windows[static_cast<std::size_t>(iteration % 3)];
    const std::vector<Ring2> polygons = random_polygons(random, window, iteration);
    if (polygons.empty()) continue;
    // strictly_apart against the union: two separate polygons whose areas add
    bool apart = true;
    for (std::size_t i = 0; i < polygons.size(); ++i)
      for (std::size_t j = i + 1; j < polygons.size(); ++j) {
        const bool fast = detail::strictly_apart(polygons[i], polygons[j]);
        const Region2 both = detail::unite_minus({polygons[i], polygons[j]});
        const bool separate = both.polygons.size() == 2 &&
                              both.area == signed_area(polygons[i]) + signed_area(polygons[j]);
        if (fast) BOOST_TEST(separate);
        apart = apart && fast;
      }
    if (!apart) continue;
    const std::optional<Region2> fast = detail::convex_difference(canonical_ring(window), polygons);
    if (!fast) continue;  // a configuration left to Polygon_set_2
    const Region2 expected = detail::unite_minus({window}, polygons);
    BOOST_TEST((*fast == expected));
    BOOST_TEST((fast->area == expected.area));
    ++tested;
    several += polygons.size() > 1;
    for (const auto& polygon : expected.polygons) holes += !polygon.holes.empty();
  }
  // the fast path must have been exercised, with several polygons and with holes
  BOOST_TEST(tested > penumbra::test::samples(1000));
  BOOST_TEST(several > penumbra::test::samples(100));
  BOOST_TEST(holes > penumbra::test::samples(10));
}

// The linear-source path (linear_face_shadow.cpp) looks for overlapping interiors among the
// pairs of shadows whose boxes meet: checked against every pair, by areas (two convex
// polygons overlap in their interiors exactly when their union is smaller than the sum of
// their areas).
BOOST_AUTO_TEST_CASE(overlapping_interiors_are_found_among_box_pairs) {
  std::mt19937 random(11);  // fixed seed
  int overlapping = 0, apart = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    const Ring2& window = windows[static_cast<std::size_t>(iteration % 3)];
    const std::vector<Ring2> shadows = random_polygons(random, window, iteration);
    bool overlap = false;
    for (std::size_t i = 0; i < shadows.size(); ++i)
      for (std::size_t j = i + 1; j < shadows.size(); ++j)
        overlap = overlap || detail::unite_minus({shadows[i], shadows[j]}).area <
                                 signed_area(shadows[i]) + signed_area(shadows[j]);
    BOOST_TEST(detail::any_interiors_overlap(shadows) == overlap);
    (overlap ? overlapping : apart) += shadows.size() > 1;
  }
  BOOST_TEST(overlapping > 100);
  BOOST_TEST(apart > 100);
}

BOOST_AUTO_TEST_SUITE_END()
