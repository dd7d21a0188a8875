// A unit cube on a floor under a point light and under the sun: shadows derived by
// hand (central and parallel projection of the cube's corners, then the convex
// hull), compared exactly with the engine.

#include <boost/test/unit_test.hpp>

#include <algorithm>

#include "shadow_support.h"
#include "support/fixtures.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

// returns the world vertices of a single-polygon region, sorted.
std::vector<Point3> world_vertices(const Region2& region, const Face& face) {
  std::vector<Point3> points;
  for (const Polygon2& polygon : region.polygons)
    for (const Point2& p : polygon.outer) points.push_back(face.frame.to_world(p));
  std::sort(points.begin(), points.end(), [](const Point3& a, const Point3& b) {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  });
  return points;
}

std::vector<Point3> sorted(std::vector<Point3> points) {
  std::sort(points.begin(), points.end(), [](const Point3& a, const Point3& b) {
    return CGAL::compare_xyz(a, b) == CGAL::SMALLER;
  });
  return points;
}

const Vector3 up(0, 0, 1), down(0, 0, -1), east(1, 0, 0), west(-1, 0, 0), north(0, 1, 0),
    south(0, -1, 0);

}  // namespace

BOOST_AUTO_TEST_SUITE(cube_shadow)

BOOST_AUTO_TEST_CASE(point_light_shadow_of_a_cube_is_the_hand_derived_hexagon) {
  const Scene scene = load_scene(fixture("scenes/shadow-cube-point.json"));
  const ShadowResult result = compute_shadows(scene);
  // Light Q = (3, 1/2, 2). A top corner P = (x, y, 1) projects from Q onto z = 0 at
  // Q + s (P - Q) with 2 + s (1 - 2) = 0, s = 2: (2x - 3, 2y - 1/2). The top square
  // goes to [-3, -1] x [-1/2, 3/2]; the bottom square [0, 1]^2 stays. Their hull:
  // (-3,-1/2) (-1,-1/2) (1,0) (1,1) (-1,3/2) (-3,3/2) — (0,0) and (0,1) are inside
  // (the line (-1,-1/2)-(1,0) passes below (0,0), (1,1)-(-1,3/2) above (0,1)).
  const FaceShadow& floor = shadow_of(scene, result, "bulb", "floor", up);
  BOOST_TEST(!floor.faces_away);
  BOOST_TEST_REQUIRE(floor.shadow.polygons.size() == 1u);
  BOOST_TEST(floor.shadow.polygons[0].holes.empty());
  const Face& floor_top = face_along(scene, "floor", up);
  BOOST_TEST((world_vertices(floor.shadow, floor_top) ==
              sorted({Point3(-3, -0.5, 0), Point3(-1, -0.5, 0), Point3(1, 0, 0), Point3(1, 1, 0),
                      Point3(-1, 1.5, 0), Point3(-3, 1.5, 0)})));
  // Shoelace over the hexagon: (1 + 1/2 + 1 + 5/2 + 3 + 6) / 2 = 7; the floor top is 8 x 8.
  BOOST_TEST(world_area_is(floor.shadow, floor_top, 7));
  BOOST_TEST(world_area_is(floor.lit, floor_top, 64 - 7));
  BOOST_TEST_REQUIRE(floor.lit.polygons.size() == 1u);
  BOOST_TEST(floor.lit.polygons[0].holes.size() == 1u);  // the shadow is a hole in the lit floor

  // Faces of the cube: F(S, Q) > 0 only for the top (2 - 1) and east (3 - 1) faces.
  for (const Vector3& normal : {west, north, south, down})
    BOOST_TEST(shadow_of(scene, result, "bulb", "cube", normal).faces_away);
  for (const Vector3& normal : {up, east}) {
    const FaceShadow& lit = shadow_of(scene, result, "bulb", "cube", normal);
    BOOST_TEST(!lit.faces_away);
    BOOST_TEST(lit.shadow.empty());
    BOOST_TEST(world_area_is(lit.lit, face_along(scene, "cube", normal), 1));
  }
}

BOOST_AUTO_TEST_CASE(sun_shadow_of_a_cube_is_the_hand_derived_rectangle) {
  const Scene scene = load_scene(fixture("scenes/shadow-cube-sun.json"));
  const ShadowResult result = compute_shadows(scene);
  // Light travels along d = (-1, 0, -1): P + t d reaches z = 0 at t = P.z, so a top
  // corner (x, y, 1) lands at (x - 1, y). Hull of [-1, 0] x [0, 1] and [0, 1]^2:
  // the rectangle [-1, 1] x [0, 1], area 2.
  const FaceShadow& floor = shadow_of(scene, result, "sun", "floor", up);
  const Face& floor_top = face_along(scene, "floor", up);
  BOOST_TEST((world_vertices(floor.shadow, floor_top) ==
              sorted({Point3(-1, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(-1, 1, 0)})));
  BOOST_TEST(world_area_is(floor.shadow, floor_top, 2));
  // n . d < 0 only for the top (n = +z) and east (n = +x) faces; north and south are
  // parallel to d (grazing), so they face away too.
  for (const Vector3& normal : {west, north, south, down})
    BOOST_TEST(shadow_of(scene, result, "sun", "cube", normal).faces_away);
  BOOST_TEST(!shadow_of(scene, result, "sun", "cube", east).faces_away);
}

BOOST_AUTO_TEST_SUITE_END()
