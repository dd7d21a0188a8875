// Two-sided planar polygons: validation (planar, convex, simple) and their two faces.

#include <boost/test/unit_test.hpp>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/geometry_error.h"

using namespace penumbra;

namespace {

// returns the index the GeometryError thrown by building the polygon names, or -2.
int failing_index(const std::vector<Point3>& cycle) {
  try {
    ConvexPolyhedron::flat_polygon(cycle);
  } catch (const GeometryError& e) {
    return e.index();
  }
  return -2;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flat_polygon)

BOOST_AUTO_TEST_CASE(square_gives_two_opposite_faces) {
  // A unit square at z = 1 with a collinear mid-edge point and a repeated point.
  const auto square = ConvexPolyhedron::flat_polygon(
      {{0, 0, 1}, {0.5, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
  BOOST_TEST(square.is_flat());
  BOOST_TEST(square.vertices().size() == 4u);
  BOOST_TEST_REQUIRE(square.faces().size() == 2u);
  // Canonical order by unit normal: (0,0,-1) before (0,0,1).
  BOOST_TEST(square.faces()[0].plane == Plane3(0, 0, -1, 1));
  BOOST_TEST(square.faces()[1].plane == Plane3(0, 0, 1, -1));
  const std::vector<Point3> up{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<Point3> down{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
  BOOST_TEST((square.faces()[1].vertices == up));
  BOOST_TEST((square.faces()[0].vertices == down));
  for (const Face& face : square.faces())
    for (int neighbour : face.neighbours)
      BOOST_TEST(neighbour == (&face == &square.faces()[0] ? 1 : 0));
  // Reversing the input cycle changes nothing.
  const auto reversed =
      ConvexPolyhedron::flat_polygon({{0, 1, 1}, {1, 1, 1}, {1, 0, 1}, {0, 0, 1}});
  BOOST_TEST(reversed.faces()[0].vertices == square.faces()[0].vertices);
  BOOST_TEST(reversed.faces()[1].vertices == square.faces()[1].vertices);
}

BOOST_AUTO_TEST_CASE(bounded_side_of_a_flat_polygon) {
  const auto triangle = ConvexPolyhedron::flat_polygon({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}});
  BOOST_TEST(triangle.bounded_side(Point3(0.5, 0.5, 0)) == CGAL::ON_BOUNDARY);
  BOOST_TEST(triangle.bounded_side(Point3(1, 1, 0)) == CGAL::ON_BOUNDARY);
  BOOST_TEST(triangle.bounded_side(Point3(1.5, 1, 0)) == CGAL::ON_UNBOUNDED_SIDE);
  BOOST_TEST(triangle.bounded_side(Point3(0.5, 0.5, 0.1)) == CGAL::ON_UNBOUNDED_SIDE);
}

BOOST_AUTO_TEST_CASE(bad_polygons_name_the_offending_point) {
  // Point 3 lifted off the plane z = 0.
  BOOST_TEST(failing_index({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.25}}) == 3);
  // A reflex vertex at index 2 (an L-shaped notch).
  BOOST_TEST(failing_index({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {2, 2, 0}, {0, 2, 0}}) >= 0);
  // A bow-tie: the cycle crosses itself although every point is extreme.
  BOOST_TEST(failing_index({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}) >= 0);
  // A point visited twice.
  BOOST_TEST(failing_index({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}) >= 0);
  // All collinear, and too few points: no index.
  BOOST_TEST(failing_index({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}) == -1);
  BOOST_TEST(failing_index({{0, 0, 0}, {1, 0, 0}}) == -1);
}

BOOST_AUTO_TEST_SUITE_END()
