// The penumbra and umbra of one occluder on one face under a linear source, by
// derivation (b) (projected contours) and (c) (clipping by the volumes), checked
// against each other, against hand-derived plates and against the exact oracles.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>

#include "linear_oracle.h"
#include "penumbra/shadow/linear_shadow.h"
#include "penumbra/shadow/shadow_loops.h"

using namespace penumbra;

namespace {

// The top face (z = 0) of the floor box [-6, 6]^2 x [-1, 0].
const Face& floor_top(const ConvexPolyhedron& floor) {
  return *std::find_if(floor.faces().begin(), floor.faces().end(),
                       [](const Face& f) { return f.plane == Plane3(0, 0, 1, 0); });
}

ConvexPolyhedron floor_box() {
  std::vector<Point3> corners;
  for (int k = 0; k < 8; ++k)
    corners.emplace_back((k & 1) ? 6 : -6, (k & 2) ? 6 : -6, (k & 4) ? 0 : -1);
  return ConvexPolyhedron::hull(corners);
}

// returns the ring's vertices as world points, sorted (rings are compared as sets
// of corners: both are convex, so the set fixes the polygon).
std::vector<Point3> world_corners(const Face& face, const Ring2& ring) {
  std::vector<Point3> points;
  for (const Point2& p : ring) points.push_back(face.frame.to_world(p));
  std::sort(points.begin(), points.end(), [](const Point3& a, const Point3& b) {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  });
  return points;
}

std::vector<Point3> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0, 0}, {x0, y1, 0}, {x1, y0, 0}, {x1, y1, 0}};
}

// returns the side of p relative to a convex counter-clockwise ring.
CGAL::Bounded_side side_of(const Ring2& ring, const Point2& p) {
  bool on_edge = false;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const CGAL::Orientation turn = CGAL::orientation(ring[k], ring[(k + 1) % ring.size()], p);
    if (turn == CGAL::RIGHT_TURN) return CGAL::ON_UNBOUNDED_SIDE;
    on_edge = on_edge || turn == CGAL::COLLINEAR;
  }
  return on_edge ? CGAL::ON_BOUNDARY : CGAL::ON_BOUNDED_SIDE;
}

// A region (the closure of the open set the oracle describes) agrees with the
// oracle when points strictly inside are blocked and points strictly outside are
// not; boundary points belong to the closure either way.
void check_oracle(const std::optional<Ring2>& ring, const Point2& p, bool blocked) {
  const CGAL::Bounded_side side = ring ? side_of(*ring, p) : CGAL::ON_UNBOUNDED_SIDE;
  if (side == CGAL::ON_BOUNDED_SIDE) BOOST_TEST(blocked);
  if (side == CGAL::ON_UNBOUNDED_SIDE) BOOST_TEST(!blocked);
}

// returns true when two non-adjacent edges of the closed loop cross or touch.
bool loop_crosses_itself(const Ring2& loop) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      const Segment2 a(loop[i], loop[(i + 1) % n]), b(loop[j], loop[(j + 1) % n]);
      if (!a.is_degenerate() && !b.is_degenerate() && CGAL::do_intersect(a, b)) return true;
    }
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_shadow)

BOOST_AUTO_TEST_CASE(square_plate_under_a_short_tube) {
  // Plate [0,1]^2 at z = 2, tube at z = 4 from x = 0.25 to x = 0.75 along y = 0.5.
  // From Q at height 4, a point of the plate projects to X = Q + 2 (v - Q) = 2v - Q:
  // from Q1 the plate covers x in [-0.25, 1.75], from Q2 x in [-0.75, 1.25], both
  // y in [-0.5, 1.5]. Umbra = the intersection, penumbra = the hull.
  const auto plate = ConvexPolyhedron::flat_polygon({{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
  const auto floor = floor_box();
  const Face& face = floor_top(floor);
  const Point3 q1(0.25, 0.5, 4), q2(0.75, 0.5, 4);
  const auto volumes = linear_volumes(plate, q1, q2);
  BOOST_TEST_REQUIRE(volumes.has_value());
  BOOST_TEST((volumes->kind == LinearCase::A));
  BOOST_TEST(projects_onto(plate, face, q1, q2));
  const auto by_volumes = clip_by_volumes(face, *volumes);
  const auto by_projection = project_contours(plate, face, q1, q2, *volumes);
  BOOST_TEST_REQUIRE((by_volumes.penumbra && by_volumes.umbra));
  BOOST_TEST(world_corners(face, *by_volumes.penumbra) == rectangle(-0.75, -0.5, 1.75, 1.5));
  BOOST_TEST(world_corners(face, *by_volumes.umbra) == rectangle(-0.25, -0.5, 1.25, 1.5));
  BOOST_TEST((by_projection.penumbra == by_volumes.penumbra));
  BOOST_TEST((by_projection.umbra == by_volumes.umbra));
}

BOOST_AUTO_TEST_CASE(long_tube_leaves_no_umbra) {
  // The same plate under a tube from x = -1 to x = 2: from Q1 the plate covers
  // x in [1, 3], from Q2 x in [-2, 0]. The two never meet: no umbra, and the
  // penumbra is the hull x in [-2, 3].
  const auto plate = ConvexPolyhedron::flat_polygon({{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
  const auto floor = floor_box();
  const Face& face = floor_top(floor);
  const Point3 q1(-1, 0.5, 4), q2(2, 0.5, 4);
  const auto volumes = linear_volumes(plate, q1, q2);
  const auto by_volumes = clip_by_volumes(face, *volumes);
  BOOST_TEST_REQUIRE(by_volumes.penumbra.has_value());
  BOOST_TEST(world_corners(face, *by_volumes.penumbra) == rectangle(-2, -0.5, 3, 1.5));
  BOOST_TEST(!by_volumes.umbra.has_value());
  const auto by_projection = project_contours(plate, face, q1, q2, *volumes);
  BOOST_TEST((by_projection.penumbra == by_volumes.penumbra));
  BOOST_TEST(!by_projection.umbra.has_value());
}

BOOST_AUTO_TEST_CASE(random_occluders_two_derivations_and_oracles_agree) {
  std::mt19937 random(1985);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> small(-2, 2), high(5, 8), spread(-4, 4), quarter(-24, 24);
  const auto floor = floor_box();
  const Face& face = floor_top(floor);
  int configurations = 0, projectable = 0, with_umbra = 0, twisted = 0;
  while (configurations < 60) {
    std::vector<Point3> points;
    for (int i = 0; i < 6; ++i)
      points.emplace_back(small(random), small(random), 1 + small(random) + 2);
    ConvexPolyhedron solid;
    try {
      solid = ConvexPolyhedron::hull(points);
    } catch (const std::exception&) {
      continue;
    }
    // Tubes mostly above the occluder; some dip below its top, so that side edges
    // of the penumbra volume miss the floor (derivation (c) only).
    const Point3 q1(spread(random), spread(random),
                    high(random) - (configurations % 5 == 0 ? 3 : 0));
    const Point3 q2(spread(random), spread(random), high(random));
    if (q1 == q2) continue;
    bool touches = false;
    for (int k = 0; k <= 32 && !touches; ++k)
      touches = solid.bounded_side(q1 + Exact(k) / 32 * (q2 - q1)) != CGAL::ON_UNBOUNDED_SIDE;
    if (touches || test::segment_meets_interior(q1, q2, solid)) continue;
    const auto volumes = linear_volumes(solid, q1, q2);
    BOOST_TEST_REQUIRE(volumes.has_value());
    const auto by_volumes = clip_by_volumes(face, *volumes);
    if (projects_onto(solid, face, q1, q2)) {
      ++projectable;
      const auto by_projection = project_contours(solid, face, q1, q2, *volumes);
      BOOST_TEST((by_projection.penumbra == by_volumes.penumbra),
                 "configuration " << configurations);
      BOOST_TEST((by_projection.umbra == by_volumes.umbra), "configuration " << configurations);
      const ShadowLoops loops = shadow_loops(solid, face, q1, q2, *volumes);
      const auto by_loops = loop_regions(face, loops);
      BOOST_TEST((by_loops.penumbra == by_volumes.penumbra), "configuration " << configurations);
      BOOST_TEST((by_loops.umbra == by_volumes.umbra), "configuration " << configurations);
      twisted += loop_crosses_itself(loops.umbra_loop);
    }
    with_umbra += by_volumes.umbra.has_value();
    for (int s = 0; s < 150; ++s) {
      const Point3 x(Exact(quarter(random)) / 4, Exact(quarter(random)) / 4, 0);
      const Point2 p = face.frame.to_frame(x);
      check_oracle(by_volumes.penumbra, p, test::triangle_blocked(x, q1, q2, solid));
      check_oracle(
          by_volumes.umbra, p,
          test::segment_meets_interior(x, q1, solid) && test::segment_meets_interior(x, q2, solid));
    }
    ++configurations;
  }
  BOOST_TEST_MESSAGE("configurations " << configurations << ", projectable " << projectable
                                       << ", with umbra " << with_umbra << ", twisted " << twisted);
  BOOST_TEST(twisted >= 3);
  BOOST_TEST(projectable >= 30);
  BOOST_TEST(with_umbra >= 10);
}

BOOST_AUTO_TEST_SUITE_END()
