// Loading every object kind, light kind and the camera of a version-1 scene.

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/scene/load_scene.h"
#include "snap_grid.h"
#include "support/fixtures.h"

using namespace penumbra;

BOOST_AUTO_TEST_SUITE(load_scene)

BOOST_AUTO_TEST_CASE(every_object_kind_loads_as_an_exact_convex_solid) {
  const Scene scene = penumbra::load_scene(test::fixture("scenes/every-kind.json"));
  BOOST_TEST(scene.warnings.empty());
  // The chair model has two parts, both closed convex solids: chair/seat and chair/back.
  BOOST_TEST_REQUIRE(scene.objects.size() == 7u);

  const Object& floor = *scene.find_object("floor");
  BOOST_TEST(floor.kind == "box");
  BOOST_TEST(floor.solid.faces().size() == 6u);
  BOOST_TEST(scene.materials[floor.material].name == "white");
  BOOST_TEST(scene.materials[floor.material].reflectance == 0.7);

  // The desk's extra points (a face centre, an edge midpoint) merge away: a box.
  const Object& desk = *scene.find_object("desk");
  BOOST_TEST(desk.solid.vertices().size() == 8u);
  BOOST_TEST(desk.solid.faces().size() == 6u);
  BOOST_TEST(scene.materials[desk.material].name == "default");

  const Object& panel = *scene.find_object("panel");
  BOOST_TEST(panel.solid.is_flat());
  BOOST_TEST(panel.solid.faces().size() == 2u);

  // Parts named by the file's objects; coordinates snapped to the 2^-20 m grid, so the
  // file's 0.42 is the grid point nearest the float 0.42f.
  const Object* seat = scene.find_object("chair/seat");
  const Object* back = scene.find_object("chair/back");
  BOOST_TEST_REQUIRE((seat && back));
  BOOST_TEST(seat->kind == "mesh");
  BOOST_TEST((seat->solid.vertices().front() == Point3(0, 0, test::on_default_grid(0.42f))));
  BOOST_TEST((back->solid.vertices().front() ==
              Point3(0, test::on_default_grid(0.40f), test::on_default_grid(0.47f))));
  BOOST_TEST(scene.mesh_faces.empty());  // convex parts are solids, not pieces
  BOOST_TEST(back->solid.faces().size() == 6u);

  const Object& tetra = *scene.find_object("tetra");
  BOOST_TEST(tetra.solid.faces().size() == 4u);

  // An 8-segment sphere: 2 poles + 8 meridians x 3 inner latitudes = 26 vertices.
  const Object& ball = *scene.find_object("ball");
  BOOST_TEST_REQUIRE(ball.sphere.has_value());
  BOOST_TEST(ball.sphere->radius == 0.5);
  BOOST_TEST(ball.solid.vertices().size() == 26u);
  for (const Point3& p : ball.solid.vertices()) {
    const Vec3d q = to_double(p);
    const double r = std::hypot(q[0] - 3, q[1] - 2, q[2] - 0.5);
    BOOST_TEST(r == 0.5, boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(lights_and_camera_keep_their_values_and_defaults) {
  const Scene scene = penumbra::load_scene(test::fixture("scenes/every-kind.json"));
  BOOST_TEST_REQUIRE(scene.lights.size() == 4u);
  const auto& bulb = std::get<PointLight>(scene.find_light("bulb")->source);
  BOOST_TEST(bulb.distribution->intensity(0.3, 1.0) == 120.0);
  // Defaults: a downward axis and C = 0 along world x.
  BOOST_TEST((bulb.axis == Vec3d{0, 0, -1}));
  BOOST_TEST((bulb.c0 == Vec3d{1, 0, 0}));
  // An axis along x takes world y, made orthogonal, as C = 0.
  const auto& aimed = std::get<PointLight>(scene.find_light("aimed")->source);
  BOOST_TEST((aimed.axis == Vec3d{1, 0, 0}));
  BOOST_TEST(std::abs(aimed.c0[0]) < 1e-15);
  BOOST_TEST(std::abs(std::abs(aimed.c0[1]) - 1) < 1e-15);

  const auto& tube = std::get<LinearLight>(scene.find_light("tube")->source);
  BOOST_TEST((tube.start == Vec3d{2, 1, 2.8}));
  BOOST_TEST(tube.candela_per_metre == 150.0);
  // The sun's direction is kept exactly as written, not normalised.
  const auto& sun = std::get<DirectionalLight>(scene.find_light("sun")->source);
  BOOST_TEST((sun.direction == Vec3d{-0.3, -0.2, -0.93}));

  BOOST_TEST_REQUIRE(scene.camera.has_value());
  BOOST_TEST((scene.camera->up == Vec3d{0, 0, 1}));
  BOOST_TEST(scene.camera->fov_deg == 50.0);
  BOOST_TEST(scene.camera->width == 320);
}

BOOST_AUTO_TEST_CASE(object_order_in_the_file_does_not_change_the_solids) {
  // Reversed vertex order of a convex object and a polygon gives the same faces.
  const Scene forward = parse_scene(R"({"penumbra": 1, "objects": [
      {"name": "a", "convex": [[0,0,0],[1,0,0],[0,1,0],[0,0,1],[0.25,0.25,0]]},
      {"name": "p", "polygon": [[0,0,2],[1,0,2],[1,1,2],[0,1,2]]}]})",
                                    "forward.json");
  const Scene backward = parse_scene(R"({"penumbra": 1, "objects": [
      {"name": "a", "convex": [[0.25,0.25,0],[0,0,1],[0,1,0],[1,0,0],[0,0,0]]},
      {"name": "p", "polygon": [[0,1,2],[1,1,2],[1,0,2],[0,0,2]]}]})",
                                     "backward.json");
  for (const char* name : {"a", "p"}) {
    const auto& f = forward.find_object(name)->solid;
    const auto& b = backward.find_object(name)->solid;
    BOOST_TEST(f.vertices() == b.vertices());
    BOOST_TEST_REQUIRE(f.faces().size() == b.faces().size());
    for (std::size_t i = 0; i < f.faces().size(); ++i) {
      BOOST_TEST(f.faces()[i].vertices == b.faces()[i].vertices);
      BOOST_TEST((f.faces()[i].plane == b.faces()[i].plane));
    }
  }
}

BOOST_AUTO_TEST_CASE(unknown_keys_warn_but_load) {
  const Scene scene = parse_scene(R"({"penumbra": 1, "colour": 3,
      "objects": [{"name": "b", "box": {"min": [0,0,0], "max": [1,1,1]}, "shiny": true}]})",
                                  "warn.json");
  BOOST_TEST(scene.objects.size() == 1u);
  BOOST_TEST_REQUIRE(scene.warnings.size() == 2u);
  BOOST_TEST(scene.warnings[0] == "warn.json: colour: unknown key, ignored");
  BOOST_TEST(scene.warnings[1] == "warn.json: objects[0].shiny: unknown key, ignored");
}

BOOST_AUTO_TEST_SUITE_END()
