// Figures 5 and 6 of Nishita 1985 rebuilt: a Case A occluder whose umbra loop
// twists, and a Case B occluder, with contours, loops and regions checked vertex by
// vertex against coordinates derived by hand below (issue #4, item 8b).

#include <boost/test/unit_test.hpp>

#include <algorithm>

#include "penumbra/shadow/contour.h"
#include "penumbra/shadow/linear_shadow.h"
#include "penumbra/shadow/shadow_loops.h"
#include "solids.h"

using namespace penumbra;

namespace {

using test::box;

// The box V = [0,1] x [0,1] x [1,2]; its vertices in canonical (x, y, z) order are
// 0 (0,0,1), 1 (0,0,2), 2 (0,1,1), 3 (0,1,2), 4 (1,0,1), 5 (1,0,2), 6 (1,1,1), 7 (1,1,2).
struct Figure {
  ConvexPolyhedron occluder = box(0, 0, 1, 1, 1, 2);
  ConvexPolyhedron floor = box(-8, -8, -1, 8, 8, 0);
  const Face& top() const {
    return *std::find_if(floor.faces().begin(), floor.faces().end(),
                         [](const Face& f) { return f.plane == Plane3(0, 0, 1, 0); });
  }
};

using Xy = std::pair<Exact, Exact>;

// returns a loop of the floor's frame as world (x, y) pairs, in order.
std::vector<Xy> world_xy(const Face& face, const Ring2& loop) {
  std::vector<Xy> points;
  for (const Point2& p : loop) {
    const Point3 world = face.frame.to_world(p);
    BOOST_TEST(world.z() == 0);
    points.emplace_back(world.x(), world.y());
  }
  return points;
}

std::vector<Xy> xy(std::initializer_list<std::pair<double, double>> points) {
  std::vector<Xy> result;
  for (const auto& [x, y] : points) result.emplace_back(x, y);
  return result;
}

// returns the ring's corners as world (x, y) pairs, sorted (a convex ring is fixed
// by its corner set).
std::vector<Xy> corners(const Face& face, const Ring2& ring) {
  std::vector<Xy> points = world_xy(face, ring);
  std::sort(points.begin(), points.end());
  return points;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_figures)

BOOST_AUTO_TEST_CASE(figure_5_case_a_with_a_twisted_umbra_loop) {
  const Figure figure;
  const Face& floor = figure.top();
  const Point3 q1(0.5, 0.5, 4), q2(3, 1.5, 4);
  const auto volumes = linear_volumes(figure.occluder, q1, q2);
  BOOST_TEST_REQUIRE(volumes.has_value());
  BOOST_TEST((volumes->kind == LinearCase::A));

  // C1: Q1 is above the centre and sees only the top face, whose counter-clockwise
  // order seen from above, (0,0,2) (1,0,2) (1,1,2) (0,1,2), reversed is C1 = [1, 3, 7, 5].
  BOOST_TEST((volumes->contour1 == std::vector<int>{1, 3, 7, 5}));
  // C2: Q2 sees the top (z = 2 < 4), x = 1 (3 > 1) and y = 1 (1.5 > 1): a hexagon along
  // the edges to the unseen faces, clockwise from Q2: [1, 3, 2, 6, 4, 5].
  BOOST_TEST((volumes->contour2 == std::vector<int>{1, 3, 2, 6, 4, 5}));
  // Tangent planes through the line Q1Q2 (direction (2.5, 1, 0)): seen along the line,
  // V is the rectangle s = -x + 2.5y in [-1, 2.5], z in [1, 2] and the line the point
  // (0.75, 4); the tangents touch (s, z) = (2.5, 2), vertex 3 (0,1,2), and (-1, 2),
  // vertex 5 (1,0,2). det[Q2-Q1, (1,0,2)-Q1, centre-Q1] = 4.375 > 0 puts V on the
  // positive side of [Q1, Q2, (1,0,2)]: that is P_R; P_L is (0,1,2).
  BOOST_TEST(volumes->left == 3);
  BOOST_TEST(volumes->right == 5);

  // Projection onto z = 0 from height 4: a vertex at z = 2 goes to 2v - Q, one at
  // z = 1 to (4v - Q)/3. From Q1 = (0.5, 0.5): 3 -> (-0.5, 1.5), 7 -> (1.5, 1.5),
  // 5 -> (1.5, -0.5), 1 -> (-0.5, -0.5). From Q2 = (3, 1.5): 5 -> (-1, -1.5),
  // 1 -> (-3, -1.5), 3 -> (-3, 0.5), 2 -> (-1, 5/6), 6 -> (1/3, 5/6), 4 -> (1/3, -0.5).
  BOOST_TEST_REQUIRE(projects_onto(figure.occluder, floor, q1, q2));
  const ShadowLoops loops = shadow_loops(figure.occluder, floor, q1, q2, *volumes);
  // Penumbra loop: C1' from P_L to P_R (3, 7, 5), then C2' from P_R to P_L (5, 1, 3).
  BOOST_TEST((world_xy(floor, loops.penumbra_loop) ==
              xy({{-0.5, 1.5}, {1.5, 1.5}, {1.5, -0.5}, {-1, -1.5}, {-3, -1.5}, {-3, 0.5}})));
  // Umbra loop: C1' from P_R to P_L (5, 1, 3), then C2' from P_L to P_R (3, 2, 6, 4, 5).
  const std::vector<Xy> umbra_loop{{1.5, -0.5},
                                   {-0.5, -0.5},
                                   {-0.5, 1.5},
                                   {-3, 0.5},
                                   {Exact(-1), Exact(5) / 6},
                                   {Exact(1) / 3, Exact(5) / 6},
                                   {Exact(1) / 3, Exact(-0.5)},
                                   {-1, -1.5}};
  BOOST_TEST((world_xy(floor, loops.umbra_loop) == umbra_loop));
  // It twists: the edge (-1, 5/6) -> (1/3, 5/6) crosses the edge (-0.5, -0.5) -> (-0.5, 1.5).
  const Segment2 crossing(loops.umbra_loop[4], loops.umbra_loop[5]);
  const Segment2 crossed(loops.umbra_loop[1], loops.umbra_loop[2]);
  BOOST_TEST(CGAL::do_intersect(crossing, crossed));

  // Umbra = C1' ∩ C2': the square [-0.5, 1.5]^2 cut by C2' (right edge x = 1/3, top
  // edge y = 5/6): the rectangle [-0.5, 1/3] x [-0.5, 5/6]. The penumbra is the hull,
  // which is the penumbra loop's hexagon.
  const std::vector<Xy> umbra{{-0.5, -0.5},
                              {Exact(-0.5), Exact(5) / 6},
                              {Exact(1) / 3, Exact(-0.5)},
                              {Exact(1) / 3, Exact(5) / 6}};
  const std::vector<Xy> penumbra =
      xy({{-3, -1.5}, {-3, 0.5}, {-1, -1.5}, {-0.5, 1.5}, {1.5, -0.5}, {1.5, 1.5}});
  for (const LinearShadowRings& rings :
       {loop_regions(floor, loops), project_contours(figure.occluder, floor, q1, q2, *volumes),
        clip_by_volumes(floor, *volumes)}) {
    BOOST_TEST_REQUIRE((rings.penumbra && rings.umbra));
    BOOST_TEST((corners(floor, *rings.umbra) == umbra));
    BOOST_TEST((corners(floor, *rings.penumbra) == penumbra));
  }
  // The loop's clockwise part is exactly one region: the umbra.
  BOOST_TEST(clockwise_regions(loops.umbra_loop).size() == 1u);
}

BOOST_AUTO_TEST_CASE(figure_6_case_b_tube_pointing_at_the_box) {
  // A vertical tube above the box's centre: its line pierces V, Case B. Q2 = (.5,.5,4)
  // is nearer, so its projected contour is the penumbra loop: the top face from
  // height 4, 2v - Q2 = the square [-0.5, 1.5]^2. Q1 = (.5,.5,6) projects z = 2 by
  // 6/4: 1.5 v - 0.5 Q1 = the square [-0.25, 1.25]^2, the umbra loop. The loops
  // never cross (section A2 (2)).
  const Figure figure;
  const Face& floor = figure.top();
  const Point3 q1(0.5, 0.5, 6), q2(0.5, 0.5, 4);
  const auto volumes = linear_volumes(figure.occluder, q1, q2);
  BOOST_TEST_REQUIRE(volumes.has_value());
  BOOST_TEST((volumes->kind == LinearCase::B));
  BOOST_TEST(!volumes->nearer_is_q1);
  const ShadowLoops loops = shadow_loops(figure.occluder, floor, q1, q2, *volumes);
  BOOST_TEST((world_xy(floor, loops.penumbra_loop) ==
              xy({{-0.5, -0.5}, {-0.5, 1.5}, {1.5, 1.5}, {1.5, -0.5}})));
  BOOST_TEST((world_xy(floor, loops.umbra_loop) ==
              xy({{-0.25, -0.25}, {-0.25, 1.25}, {1.25, 1.25}, {1.25, -0.25}})));
  for (const LinearShadowRings& rings :
       {loop_regions(floor, loops), project_contours(figure.occluder, floor, q1, q2, *volumes),
        clip_by_volumes(floor, *volumes)}) {
    BOOST_TEST_REQUIRE((rings.penumbra && rings.umbra));
    BOOST_TEST((corners(floor, *rings.penumbra) ==
                xy({{-0.5, -0.5}, {-0.5, 1.5}, {1.5, -0.5}, {1.5, 1.5}})));
    BOOST_TEST((corners(floor, *rings.umbra) ==
                xy({{-0.25, -0.25}, {-0.25, 1.25}, {1.25, -0.25}, {1.25, 1.25}})));
  }
}

BOOST_AUTO_TEST_SUITE_END()
