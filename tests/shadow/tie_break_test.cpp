// Each stated tie-break of docs/shadows.md on its fixture, with the expected
// shadow derived by hand in the comments (the oracle test checks the same fixtures
// point by point).

#include <boost/test/unit_test.hpp>

#include "shadow_support.h"
#include "support/fixtures.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

const Vector3 up(0, 0, 1), down(0, 0, -1), east(1, 0, 0), west(-1, 0, 0), north(0, 1, 0),
    south(0, -1, 0);

ShadowResult shade(const Scene& scene) {
  ShadowOptions options;
  options.range_fraction = 0;
  return compute_shadows(scene, options);
}

bool in_region(const Region2& region, const Face& face, const Point3& p) {
  return locate(region, face.frame.to_frame(p)) == Where::inside;
}

bool casts_anything(const Scene& scene, const ShadowResult& result, const std::string& object) {
  for (const LightShadows& light : result.lights)
    for (const FaceShadow& face : light.faces)
      for (const OccluderShadow& occluder : face.occluders)
        if (scene.objects[occluder.occluder].name == object) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tie_breaks)

BOOST_AUTO_TEST_CASE(occluders_touching_the_face_shadow_from_the_contact) {
  const Scene scene = load_scene(fixture("scenes/shadow-touching.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  const FaceShadow& floor = shadow_of(scene, result, "bulb", "floor", up);
  // Q = (1, 1, 3); the tops (z = 1) project with s = 3 / 2. Wedge top [0, 2]^2 ->
  // [-1/2, 5/2]^2, containing the contact edge x = 1: area 9. Pyramid top [-3, -1]^2 ->
  // [-5, -2]^2, hull with the touching apex (-2, -2), cut by the floor at -4: [-4, -2]^2.
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "wedge"), top, 9));
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "pyramid"), top, 4));
  BOOST_TEST(world_area_is(floor.shadow, top, 13));
  BOOST_TEST(floor.shadow.polygons.size() == 2u);
}

BOOST_AUTO_TEST_CASE(occluders_cutting_the_face_shadow_their_section_and_beyond) {
  const Scene scene = load_scene(fixture("scenes/shadow-cutting.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  const FaceShadow& floor = shadow_of(scene, result, "bulb", "floor", up);
  // Q = (2, 2, 2). Only the post's part above z = 0 counts: its section [0, 1]^2 stays,
  // its top (s = 2) lands on [-2, 0]^2. Hull (-2,-2) (0,-2) (1,0) (1,1) (0,1) (-2,0),
  // shoelace (4 + 2 + 1 + 1 + 2 + 4) / 2 = 7.
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "post"), top, 7));
  BOOST_TEST(in_region(floor.shadow, top, Point3(0.5, 0.5, 0)));  // inside the post's section
  BOOST_TEST(!in_region(floor.shadow, top, Point3(1.5, 1.5, 0)));
}

BOOST_AUTO_TEST_CASE(occluders_behind_the_light_cast_nothing_and_straddling_ones_are_cut) {
  const Scene scene = load_scene(fixture("scenes/shadow-behind-light.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  const FaceShadow& floor = shadow_of(scene, result, "bulb", "floor", up);
  // Q = (0, 0, 2); "above" lies beyond the light: nothing.
  BOOST_TEST(!casts_anything(scene, result, "above"));
  // "below": its top z = 3/2 projects with s = 4: [-2, 2]^2, area 16.
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "below"), top, 16));
  // "beside" straddles the light's level: only its part below z = 2 counts, and its
  // shadow runs to infinity. Its west face x = 3/4 seen from Q gives the points
  // (3/4 s, y s) with s = 2 / (2 - z) >= 4, |y| <= 1/4: x >= 3, |y| <= x / 3. Cut by
  // the floor's edge x = 4: the trapezoid (3, -1) (4, -4/3) (4, 4/3) (3, 1), area 7/3.
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "beside"), top, Exact(7) / 3));
  BOOST_TEST(world_area_is(floor.shadow, top, Exact(55) / 3));
}

BOOST_AUTO_TEST_CASE(faces_in_contact_shadow_each_other_and_coplanar_faces_do_not) {
  const Scene scene = load_scene(fixture("scenes/shadow-shared-face.json"));
  const ShadowResult result = shade(scene);
  for (const char* light : {"bulb", "sun"}) {
    // The upper box's bottom touches the lower box's top: the contact square is in
    // shadow (a segment from it enters the upper box at once); the bottom faces away.
    BOOST_TEST(shadow_of(scene, result, light, "upper", down).faces_away);
    BOOST_TEST(in_region(shadow_of(scene, result, light, "lower", up).shadow,
                         face_along(scene, "lower", up), Point3(1, 1, 1)));
    // twin-a and twin-b overlap with coplanar tops: neither shades the other's top.
    BOOST_TEST(
        occluder_region(scene, shadow_of(scene, result, light, "twin-a", up), "twin-b").empty());
    BOOST_TEST(
        occluder_region(scene, shadow_of(scene, result, light, "twin-b", up), "twin-a").empty());
  }
  // The bulb (-3, -5/2, 3) sees the west face x = -1 of "right"; "left" sits against its
  // lower half (z < 1), so (-1, -5/2, 1/2) is in shadow and (-1, -5/2, 19/10) is lit.
  const Face& west_face = face_along(scene, "right", west);
  const FaceShadow& right = shadow_of(scene, result, "bulb", "right", west);
  BOOST_TEST(in_region(right.shadow, west_face, Point3(-1, -2.5, 0.5)));
  BOOST_TEST(in_region(right.lit, west_face, Point3(-1, -2.5, 1.9)));
  BOOST_TEST(shadow_of(scene, result, "bulb", "left", east).faces_away);
}

BOOST_AUTO_TEST_CASE(light_in_the_plane_of_a_face_leaves_it_unlit_and_bounds_the_shadow) {
  const Scene scene = load_scene(fixture("scenes/shadow-light-in-plane.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  // "level" Q = (5/2, 1/2, 1) lies in the plane of the box's top: the top is unlit.
  BOOST_TEST(shadow_of(scene, result, "level", "box", up).faces_away);
  BOOST_TEST(!shadow_of(scene, result, "level", "box", east).faces_away);
  // The box's shadow on the floor through its east face x = 1: points Q + s (P - Q),
  // s = 1 / (1 - z) >= 1, i.e. x <= 1 and |y - 1/2| <= (5/2 - x) / 3; cut at x = -4: a
  // trapezoid of width 5 and sides 1 and 13/3, area 40/3. The wall (y in [3, 7/2], up to
  // z = 2) shadows the strip y in [3, 4] behind and under it: 8. Total 64/3.
  const FaceShadow& floor = shadow_of(scene, result, "level", "floor", up);
  BOOST_TEST(world_area_is(occluder_region(scene, floor, "box"), top, Exact(40) / 3));
  BOOST_TEST(world_area_is(floor.shadow, top, Exact(64) / 3));
  // "card-plane" lies in the card's plane: a two-sided polygon seen edge-on casts nothing.
  ShadowOptions card_only;
  card_only.light = "card-plane";
  card_only.range_fraction = 0;
  BOOST_TEST(!casts_anything(scene, compute_shadows(scene, card_only), "card"));
  // "grazing" lies in the floor's top plane: the top is wholly unlit.
  const FaceShadow& grazed = shadow_of(scene, result, "grazing", "floor", up);
  BOOST_TEST(grazed.faces_away);
  BOOST_TEST(world_area_is(grazed.shadow, top, 64));
  BOOST_TEST(grazed.lit.empty());
}

BOOST_AUTO_TEST_CASE(sun_parallel_to_a_face_leaves_it_unlit) {
  const Scene scene = load_scene(fixture("scenes/shadow-sun-parallel.json"));
  const ShadowResult result = shade(scene);
  // "horizon" travels along -x: parallel to every face with a normal in y or z.
  for (const char* object : {"floor", "box"})
    for (const Vector3& normal : {up, north, south})
      BOOST_TEST(shadow_of(scene, result, "horizon", object, normal).faces_away);
  // The box [0, 1]^3 shadows the wall's east face x = -5/2 on y, z in [0, 1]: area 1.
  const FaceShadow& wall = shadow_of(scene, result, "horizon", "wall", east);
  BOOST_TEST(world_area_is(wall.shadow, face_along(scene, "wall", east), 1));
  // The sheet is horizontal, parallel to "horizon": no shadow; under "oblique" it casts.
  ShadowOptions horizon;
  horizon.light = "horizon";
  BOOST_TEST(!casts_anything(scene, compute_shadows(scene, horizon), "sheet"));
  for (const Vector3& normal : {north, south})
    BOOST_TEST(shadow_of(scene, result, "oblique", "box", normal).faces_away);
}

BOOST_AUTO_TEST_CASE(shadows_that_abut_merge_into_one_polygon) {
  const Scene scene = load_scene(fixture("scenes/shadow-abutting.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  // Straight down, a, b and c cover [0,1]^2, [1,2]x[0,1], [0,2]x[1,2]: the square [0,2]^2.
  // From Q = (1, 1, 3) their tops (z = 3/2, s = 2) give [-1,1]^2, [1,3]x[-1,1] and
  // [-1,3]x[1,3]: the square [-1,3]^2.
  for (const auto& [light, area] : {std::pair{"sun", 4}, std::pair{"bulb", 16}}) {
    const FaceShadow& floor = shadow_of(scene, result, light, "floor", up);
    BOOST_TEST_REQUIRE(floor.shadow.polygons.size() == 1u, light);
    BOOST_TEST(floor.shadow.polygons[0].outer.size() == 4u, light);
    BOOST_TEST(floor.shadow.polygons[0].holes.empty());
    BOOST_TEST(world_area_is(floor.shadow, top, area), light);
    BOOST_TEST(floor.occluders.size() == 3u);
  }
}

BOOST_AUTO_TEST_CASE(collinear_contour_vertices_give_a_canonical_polygon) {
  const Scene scene = load_scene(fixture("scenes/shadow-collinear-contour.json"));
  const ShadowResult result = shade(scene);
  const Face& top = face_along(scene, "floor", up);
  // Q = (1, 1/2, 3) lies in the plane x = 1 of the cube's east face: its top corners
  // (s = 3/2) and bottom corners (z = 1/2, s = 6/5) on x = 1 project onto one line. The
  // hull is the rectangle [-1/2, 1] x [-1/4, 5/4] with 4 vertices, area 9/4.
  const FaceShadow& floor = shadow_of(scene, result, "bulb", "floor", up);
  const Region2 cube = occluder_region(scene, floor, "cube");
  BOOST_TEST_REQUIRE(cube.polygons.size() == 1u);
  BOOST_TEST(cube.polygons[0].outer.size() == 4u);
  BOOST_TEST(world_area_is(cube, top, Exact(9) / 4));
  // Sun along (0, 1, -1): (x, y, z) lands at (x, y + z). The prism's base corners give
  // [-2, -1] x [1/2, 3/2], its ridge (-3/2, y, 1) gives x = -3/2, y in [1, 2]: a pentagon
  // of area 1 + 1/4; the cube gives [0, 1] x [1/2, 2], area 3/2.
  const FaceShadow& sunny = shadow_of(scene, result, "sun", "floor", up);
  const Region2 prism = occluder_region(scene, sunny, "prism");
  BOOST_TEST_REQUIRE(prism.polygons.size() == 1u);
  BOOST_TEST(prism.polygons[0].outer.size() == 5u);
  BOOST_TEST(world_area_is(prism, top, Exact(5) / 4));
  BOOST_TEST(world_area_is(sunny.shadow, top, Exact(11) / 4));
}

// A ring that touches itself at its smallest vertex O = (0, 0): two counter-clockwise
// loops, O (1, -2) (2, -1) and O (2, 1) (1, 2) (cross products 1 * -1 - -2 * 2 = 3 and
// 2 * 2 - 1 * 1 = 3). Traced from either pass through O it is one canonical ring: the pass
// followed by (1, -2), the smaller of (1, -2) and (2, 1).
BOOST_AUTO_TEST_CASE(a_ring_touching_itself_at_its_smallest_vertex_starts_at_one_pass) {
  const Point2 o(0, 0), a(1, -2), b(2, -1), c(2, 1), d(1, 2);
  const Ring2 expected{o, a, b, o, c, d};
  for (const Ring2& traced : {Ring2{o, a, b, o, c, d}, Ring2{o, c, d, o, a, b},
                              Ring2{c, d, o, a, b, o}, Ring2{b, o, c, d, o, a}}) {
    const Ring2 ring = canonical_ring(traced);
    BOOST_TEST_REQUIRE(ring.size() == expected.size());
    for (std::size_t k = 0; k < ring.size(); ++k) BOOST_TEST((ring[k] == expected[k]));
  }
}

BOOST_AUTO_TEST_CASE(light_inside_or_on_an_occluder_darkens_everything_else) {
  const Scene scene = load_scene(fixture("scenes/shadow-light-inside.json"));
  const ShadowResult result = shade(scene);
  for (const LightShadows& light : result.lights)
    for (std::size_t r = 0; r < result.receivers.size(); ++r) {
      const Object& object = scene.objects[result.receivers[r].object];
      BOOST_TEST(light.faces[r].lit.empty(), object.name << " face " << result.receivers[r].face);
      if (object.name == "lantern") BOOST_TEST(light.faces[r].faces_away);
    }
}

BOOST_AUTO_TEST_SUITE_END()
