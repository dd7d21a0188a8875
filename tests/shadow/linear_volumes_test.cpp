// Contours, Case A/B, P_L and P_R, and the shadow, umbra and penumbra volumes of a
// linear source (Nishita 1985 section 4.1, Appendix A2), checked against exact
// oracles, a second construction by convex hull, and hand-derived cases.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>

#include "linear_oracle.h"
#include "penumbra/shadow/contour.h"
#include "penumbra/shadow/linear_volumes.h"

using namespace penumbra;

namespace {

ConvexPolyhedron unit_cube() {
  std::vector<Point3> corners;
  for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  return ConvexPolyhedron::hull(corners);
}

int vertex_id(const ConvexPolyhedron& solid, const Point3& p) {
  const auto& v = solid.vertices();
  return static_cast<int>(std::find(v.begin(), v.end(), p) - v.begin());
}

bool same_plane_sets(std::vector<Plane3> a, std::vector<Plane3> b) {
  if (a.size() != b.size()) return false;
  for (const Plane3& p : a)
    if (std::find(b.begin(), b.end(), p) == b.end()) return false;
  return true;
}

// Checks the contour's two defining properties independently of how it was found:
// every contour edge spans a plane with the source that supports the solid, and the
// loop turns clockwise seen from the source around the solid's centroid.
void check_contour(const ConvexPolyhedron& solid, const Point3& q, const std::vector<int>& loop) {
  Vector3 sum = CGAL::NULL_VECTOR;
  for (const Point3& p : solid.vertices()) sum = sum + (p - CGAL::ORIGIN);
  const Point3 centre = CGAL::ORIGIN + sum / static_cast<int>(solid.vertices().size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point3& a = solid.vertices()[loop[i]];
    const Point3& b = solid.vertices()[loop[(i + 1) % loop.size()]];
    BOOST_TEST(CGAL::orientation(q, a, b, centre) == CGAL::POSITIVE);
    bool below = true, above = true;
    for (const Point3& x : solid.vertices()) {
      below = below && CGAL::orientation(q, a, b, x) != CGAL::NEGATIVE;
      above = above && CGAL::orientation(q, a, b, x) != CGAL::POSITIVE;
    }
    BOOST_TEST((below || above));
  }
}

// A random rational point with small denominators, so that many samples fall
// exactly on the volumes' planes and test the open/closed tie-breaks.
Point3 random_point(std::mt19937& random, int range) {
  std::uniform_int_distribution<int> numerator(-4 * range, 4 * range);
  return Point3(Exact(numerator(random)) / 4, Exact(numerator(random)) / 4,
                Exact(numerator(random)) / 4);
}

// Samples points and compares every volume with the oracles; returns the number of
// points that were in the penumbra volume (so that the caller can see coverage).
int check_against_oracles(const ConvexPolyhedron& solid, const Point3& q1, const Point3& q2,
                          const LinearVolumes& volumes, std::mt19937& random, int samples) {
  int shadowed = 0;
  for (int s = 0; s < samples; ++s) {
    const Point3 x = random_point(random, 6);
    const bool from_q1 = test::segment_meets_interior(x, q1, solid);
    const bool from_q2 = test::segment_meets_interior(x, q2, solid);
    const bool penumbra = test::triangle_blocked(x, q1, q2, solid);
    BOOST_TEST(volumes.shadow1.contains(x) == from_q1);
    BOOST_TEST(volumes.shadow2.contains(x) == from_q2);
    BOOST_TEST(volumes.umbra.contains(x) == (from_q1 && from_q2));
    BOOST_TEST(volumes.penumbra.contains(x) == penumbra);
    shadowed += penumbra;
  }
  return shadowed;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_volumes)

BOOST_AUTO_TEST_CASE(contour_of_a_cube_seen_from_above_is_its_top_face_clockwise) {
  const auto cube = unit_cube();
  // Seen from above, the top face's counter-clockwise order (0,0,1) (1,0,1) (1,1,1)
  // (0,1,1) reverses: clockwise from (0,0,1) it is (0,0,1) (0,1,1) (1,1,1) (1,0,1).
  const std::vector<int> expected{vertex_id(cube, {0, 0, 1}), vertex_id(cube, {0, 1, 1}),
                                  vertex_id(cube, {1, 1, 1}), vertex_id(cube, {1, 0, 1})};
  BOOST_TEST(contour(cube, Point3(0.5, 0.5, 5)) == expected);
  // Seen from a corner direction, three faces are turned toward the source: a hexagon.
  const Point3 corner(3, 2.5, 2);
  const auto hexagon = contour(cube, corner);
  BOOST_TEST(hexagon.size() == 6u);
  check_contour(cube, corner, hexagon);
  // From inside, or on the solid, no face is turned toward the source.
  BOOST_TEST(contour(cube, Point3(0.5, 0.5, 0.5)).empty());
  BOOST_TEST(contour(cube, Point3(0.5, 0.5, 1)).empty());
}

BOOST_AUTO_TEST_CASE(source_in_the_plane_of_a_face_keeps_the_edge_on_face_out) {
  // Q in the plane z = 1 of the top face: the top is edge-on (F = 0), not turned
  // toward Q; only the face x = 1 is, so the contour is that face's boundary.
  const auto cube = unit_cube();
  const Point3 q(3, 0.5, 1);
  const auto loop = contour(cube, q);
  BOOST_TEST(loop.size() == 4u);
  for (int v : loop) BOOST_TEST(cube.vertices()[v].x() == 1);
  check_contour(cube, q, loop);
}

BOOST_AUTO_TEST_CASE(case_a_tube_across_a_cube) {
  // A tube above the cube, oblique so that the tangent planes through its line
  // touch the cube at single vertices.
  const auto cube = unit_cube();
  const Point3 q1(-1, 0.25, 3), q2(2, 0.5, 3.5);
  const auto volumes = penumbra::linear_volumes(cube, q1, q2);
  BOOST_TEST_REQUIRE(volumes.has_value());
  BOOST_TEST((volumes->kind == LinearCase::A));
  // P_L and P_R lie on both contours, on opposite sides (y = 0 and y = 1 edges).
  BOOST_TEST(cube.vertices()[volumes->left].z() == 1);
  BOOST_TEST(cube.vertices()[volumes->right].z() == 1);
  BOOST_TEST(cube.vertices()[volumes->left].y() != cube.vertices()[volumes->right].y());
  BOOST_TEST(same_plane_sets(volumes->penumbra.planes, penumbra_planes_by_hull(cube, q1, q2)));
  std::mt19937 random(41);  // fixed: the sample points are part of the test
  BOOST_TEST(check_against_oracles(cube, q1, q2, *volumes, random, 1500) > 50);
}

BOOST_AUTO_TEST_CASE(case_b_tube_pointing_at_a_cube) {
  // The tube's line x = y = 0.5 pierces the cube below it: Case B. Q2 is nearer,
  // so U2 encloses U1 and is the penumbra volume (App. A2 (2)).
  const auto cube = unit_cube();
  const Point3 q1(0.5, 0.5, 4), q2(0.5, 0.5, 2);
  const auto volumes = penumbra::linear_volumes(cube, q1, q2);
  BOOST_TEST_REQUIRE(volumes.has_value());
  BOOST_TEST((volumes->kind == LinearCase::B));
  BOOST_TEST(!volumes->nearer_is_q1);
  BOOST_TEST(same_plane_sets(volumes->penumbra.planes, penumbra_planes_by_hull(cube, q1, q2)));
  std::mt19937 random(42);  // fixed: the sample points are part of the test
  BOOST_TEST(check_against_oracles(cube, q1, q2, *volumes, random, 1500) > 50);
}

BOOST_AUTO_TEST_CASE(coplanar_contour_edges_give_the_same_volumes_for_every_choice) {
  // The tube runs parallel to the cube's top edges along x: each tangent plane
  // through its line contains a whole top edge, so two vertices qualify as P_L and
  // two as P_R (App. A2: "two arbitrary vertices are selected").
  const auto cube = unit_cube();
  const Point3 q1(-1, 0.5, 3), q2(2, 0.5, 3);
  const auto [lefts, rights] = tangent_vertices(cube, q1, q2);
  BOOST_TEST(lefts.size() == 2u);
  BOOST_TEST(rights.size() == 2u);
  const auto chosen = penumbra::linear_volumes(cube, q1, q2);
  BOOST_TEST_REQUIRE(chosen.has_value());
  const auto hull_planes = penumbra_planes_by_hull(cube, q1, q2);
  BOOST_TEST(same_plane_sets(chosen->penumbra.planes, hull_planes));
  for (int left : lefts)
    for (int right : rights) {
      const auto [penumbra, umbra] =
          case_a_volumes(cube, q1, q2, chosen->contour1, chosen->contour2, left, right);
      BOOST_TEST(same_plane_sets(penumbra.planes, hull_planes));
      BOOST_TEST(same_plane_sets(umbra.planes, chosen->umbra.planes));
    }
  std::mt19937 random(43);  // fixed: the sample points are part of the test
  check_against_oracles(cube, q1, q2, *chosen, random, 1000);
}

BOOST_AUTO_TEST_CASE(random_occluders_and_tubes_agree_with_the_oracles_and_the_hull) {
  // Integer coordinates on a small grid make coplanar and collinear configurations
  // frequent: tubes parallel to edges, in face planes, through vertices' planes.
  std::mt19937 random(20261122);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> small(-2, 2), far(-6, 6);
  int configurations = 0, case_b = 0;
  while (configurations < 40) {
    std::vector<Point3> points;
    for (int i = 0; i < 7; ++i) points.emplace_back(small(random), small(random), small(random));
    ConvexPolyhedron solid;
    try {
      solid = ConvexPolyhedron::hull(points);
    } catch (const std::exception&) {
      continue;
    }
    const Point3 q2(far(random), far(random), far(random));
    // Every other configuration aims the tube's line at a vertex or through the
    // solid (Case B, including the line touching it at a vertex).
    const Point3 aim = configurations % 4 == 1
                           ? solid.vertices()[0]
                           : CGAL::midpoint(solid.vertices()[0], solid.vertices().back());
    const Point3 q1 = configurations % 2 == 1 ? q2 + (q2 - aim) / 2
                                              : Point3(far(random), far(random), far(random));
    if (q1 == q2 || test::segment_meets_interior(q1, q2, solid) ||
        solid.bounded_side(q1) != CGAL::ON_UNBOUNDED_SIDE ||
        solid.bounded_side(q2) != CGAL::ON_UNBOUNDED_SIDE)
      continue;
    // The closed segment must miss the closed solid (the precondition).
    bool touches = false;
    for (int k = 0; k <= 16 && !touches; ++k)
      touches = solid.bounded_side(q1 + Exact(k) / 16 * (q2 - q1)) != CGAL::ON_UNBOUNDED_SIDE;
    if (touches) continue;
    const auto volumes = penumbra::linear_volumes(solid, q1, q2);
    BOOST_TEST_REQUIRE(volumes.has_value());
    case_b += volumes->kind == LinearCase::B;
    BOOST_TEST(same_plane_sets(volumes->penumbra.planes, penumbra_planes_by_hull(solid, q1, q2)),
               "configuration " << configurations);
    check_contour(solid, q1, volumes->contour1);
    check_contour(solid, q2, volumes->contour2);
    check_against_oracles(solid, q1, q2, *volumes, random, 250);
    ++configurations;
  }
  BOOST_TEST_MESSAGE("random configurations: " << configurations << ", Case B: " << case_b);
  BOOST_TEST(case_b >= 15);
}

// exact_point_shadow_planes builds U_r in rationals for the exact umbra's prepared solids:
// its planes must be point_shadow_volume's, coefficient for coefficient and in order (the
// sweep's lines, hence its outputs, are made from them), and independently of either, a
// point lies strictly inside every plane exactly when the segment from it to the source
// is blocked by the solid (section 4.1.1). Small integer grids put sources in the
// planes of faces and on the lines of edges; flat polygons are two-sided solids.
BOOST_AUTO_TEST_CASE(exact_point_shadow_planes_are_the_volumes_planes_in_rationals) {
  std::mt19937 random(20261206);  // fixed: failures must reproduce
  std::uniform_int_distribution<int> small(-2, 2), far(-4, 4);
  int solids = 0, flat = 0, empty = 0, in_face_planes = 0, inside = 0;
  while (solids < 60) {
    ConvexPolyhedron solid;
    try {
      if (solids % 5 == 4) {
        // a triangle or a square in a random plane through integer points
        const Point3 a(small(random), small(random), small(random));
        const Vector3 u(small(random), small(random), small(random));
        const Vector3 v(small(random), small(random), small(random));
        if (CGAL::cross_product(u, v) == CGAL::NULL_VECTOR) continue;
        std::vector<Point3> cycle{a, a + u, a + u + v};
        if (solids % 10 == 4) cycle.push_back(a + v);
        solid = ConvexPolyhedron::flat_polygon(cycle);
      } else {
        std::vector<Point3> points;
        for (int i = 0; i < 7; ++i)
          points.emplace_back(small(random), small(random), small(random));
        solid = ConvexPolyhedron::hull(points);
      }
    } catch (const std::exception&) {
      continue;
    }
    const Point3 q(far(random), far(random), far(random));
    if (solid.bounded_side(q) != CGAL::ON_UNBOUNDED_SIDE) continue;
    std::vector<RationalPoint3> vertices;
    for (const Point3& p : solid.vertices()) vertices.push_back(exact_value(p));
    std::vector<RationalPlane3> faces;
    for (const Face& face : solid.faces()) {
      faces.push_back(exact_value(face.plane));
      in_face_planes += face.plane.has_on(q);
    }
    const std::vector<Plane3> expected = point_shadow_volume(solid, q).planes;
    const std::vector<RationalPlane3> planes = exact_point_shadow_planes(solid, vertices, faces, q);
    BOOST_TEST_REQUIRE(planes.size() == expected.size(), "solid " << solids);
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const RationalPlane3 e = exact_value(expected[k]);
      BOOST_TEST((planes[k].a() == e.a() && planes[k].b() == e.b() && planes[k].c() == e.c() &&
                  planes[k].d() == e.d()),
                 "solid " << solids << " plane " << k);
    }
    for (int s = 0; s < 60; ++s) {
      const Point3 x = random_point(random, 5);
      const RationalPoint3 rx = exact_value(x);
      const bool in = !planes.empty() &&
                      std::all_of(planes.begin(), planes.end(), [&](const RationalPlane3& plane) {
                        return plane.oriented_side(rx) == CGAL::ON_NEGATIVE_SIDE;
                      });
      BOOST_TEST(in == test::point_blocked(x, q, solid), "solid " << solids);
      inside += in;
    }
    flat += solid.is_flat();
    empty += planes.empty();
    ++solids;
  }
  BOOST_TEST_MESSAGE("solids " << solids << ", flat " << flat << ", sources in a face's plane "
                               << in_face_planes << ", points inside " << inside);
  BOOST_TEST(flat >= 10);
  BOOST_TEST(in_face_planes >= 5);
  BOOST_TEST(inside >= 100);
}

BOOST_AUTO_TEST_SUITE_END()
