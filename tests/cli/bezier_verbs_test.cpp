// Objects of Bézier patches through every verb (issue #23): raytrace intersects the patches
// (its image is the reference one, looked at when made); shadows, illuminance, render and
// radiosity see the tessellation and say so. The ground's shadow under a vertical sun is
// checked against the exact patches: sample points whose vertical ray meets (misses) the
// patches, with their neighbours at twice the tolerance agreeing, lie in (out of) the
// shadow polygons of the tessellation.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "penumbra/base/random.h"
#include "penumbra/raytrace/embree_scene.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/scene/scene.h"
#include "support/fixtures.h"
#include "support/heavy.h"

using penumbra::test::fixture;
using penumbra::test::run_penumbra;

namespace {

// The tessellation's tolerance: coarser under the sanitizers (support/heavy.h), where
// shadows and radiosity over the finer one take a minute each.
constexpr double kTolerance = penumbra::test::sanitized() ? 0.05 : 0.02;

std::filesystem::path teapot_scene() {
  const auto dir = penumbra::test::scratch_dir("bezier-verbs");
  nlohmann::json scene = {
      {"penumbra", 1},
      {"materials", {{"glaze", {{"reflectance", 0.6}, {"specular", 0.4}, {"shininess", 60}}}}},
      {"objects",
       {{{"name", "ground"}, {"box", {{"min", {-3, -3, -0.1}}, {"max", {3, 3, 0}}}}},
        {{"name", "teapot"},
         {"bezier_patches", fixture("meshes/teapot.bpt").string()},
         {"scale", 0.25},
         {"tolerance", kTolerance},
         {"material", "glaze"}}}},
      {"lights",
       {{{"name", "sun"}, {"directional", {0, 0, -1}}, {"illuminance", 50000}},
        {{"name", "lamp"}, {"point", {1, -1, 2}}, {"candela", 500}}}},
      {"camera", {{"eye", {2, -3, 2}}, {"target", {0, 0, 0.3}}, {"width", 64}, {"height", 48}}}};
  std::ofstream(dir / "scene.json") << scene.dump();
  return dir / "scene.json";
}

// returns true when (x, y) lies inside ring (a list of [x, y, z] points), by crossings.
bool inside_ring(const nlohmann::json& ring, double x, double y) {
  bool inside = false;
  for (std::size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++) {
    const double xi = ring[k][0], yi = ring[k][1], xj = ring[j][0], yj = ring[j][1];
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

bool in_polygons(const nlohmann::json& polygons, double x, double y) {
  for (const auto& polygon : polygons) {
    if (!inside_ring(polygon["outer"], x, y)) continue;
    bool in_hole = false;
    for (const auto& hole : polygon["holes"]) in_hole = in_hole || inside_ring(hole, x, y);
    if (!in_hole) return true;
  }
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bezier_verbs)

BOOST_AUTO_TEST_CASE(the_teapots_render_as_their_reference_images, PENUMBRA_HEAVY_TEST) {
  const auto dir = penumbra::test::scratch_dir("bezier-images");
  for (const std::string name : {"bezier-teapot", "bezier-glass"}) {
    const auto image = dir / (name + ".png");
    const auto result =
        run_penumbra("raytrace fixtures/scenes/" + name + ".json -o '" + image.string() + "'");
    BOOST_TEST_REQUIRE(result.status == 0, result.err);
    BOOST_TEST(result.err.find("32 Bézier patches tessellated") != std::string::npos);
    BOOST_TEST(penumbra::test::read_text(image) ==
                   penumbra::test::read_text(fixture("images/" + name + ".png")),
               name);
  }
}

BOOST_AUTO_TEST_CASE(every_verb_runs_and_the_exact_ones_name_the_tessellation) {
  const auto scene = teapot_scene();
  const auto dir = scene.parent_path();
  const std::string s = "'" + scene.string() + "'";
  const auto out = [&](const std::string& name) { return "'" + (dir / name).string() + "'"; };
  const auto shadows = run_penumbra("shadows " + s + " -o " + out("loops.json"));
  BOOST_TEST_REQUIRE(shadows.status == 0, shadows.err);
  BOOST_TEST(shadows.err.find("every verb but raytrace uses the tessellation") !=
             std::string::npos);
  const nlohmann::json document = nlohmann::json::parse(std::ifstream(dir / "loops.json"));
  const penumbra::Scene loaded = penumbra::load_scene(scene);
  BOOST_TEST_REQUIRE(document["tessellated"].size() == 1u);
  BOOST_TEST(document["tessellated"][0]["object"] == "teapot");
  BOOST_TEST(document["tessellated"][0]["patches"] == 32);
  BOOST_TEST(document["tessellated"][0]["triangles"] == loaded.tessellated.at(0).triangles);
  BOOST_TEST(document["tessellated"][0]["tolerance"] == kTolerance);
  for (const std::string& verb :
       {"illuminance " + s + " --workplane 0.01 --spacing 0.5 -o " + out("grid.csv"),
        "render " + s + " -o " + out("render.png"),
        "raytrace " + s + " -o " + out("ray.png") + " --values " + out("ray.csv"),
        "radiosity " + s + " --patch-size 0.5 --rays 64 -o " + out("patches.csv")}) {
    const auto result = run_penumbra(verb);
    BOOST_TEST(result.status == 0, verb << ": " << result.err);
  }

  // The values name the patch object, not a piece of its tessellation.
  const std::string values = penumbra::test::read_text(dir / "ray.csv");
  BOOST_TEST(values.find(",teapot,") != std::string::npos);
  BOOST_TEST(values.find("teapot#") == std::string::npos);

  // The ground's top face and its shadow from the vertical sun.
  nlohmann::json shadow;
  for (const auto& face : document["faces"])
    if (face["object"] == "ground" && face["frame"]["u"][2] == 0.0 && face["boundary"][0][2] == 0.0)
      for (const auto& light : face["lights"])
        if (light["light"] == "sun") shadow = light["shadow"]["polygons"];
  BOOST_TEST_REQUIRE(!shadow.is_null());
  BOOST_TEST_REQUIRE(!shadow.empty());
  const penumbra::raytrace::EmbreeScene exact(loaded);
  const auto on_teapot = [&](double x, double y) {
    const auto hit = exact.intersect({{x, y, 2}, {0, 0, -1}});
    return hit && loaded.objects[hit->object].face_owner() == "teapot";
  };
  penumbra::SplitMix64 random(23);
  int inside = 0, outside = 0, near_edge = 0;
  for (int k = 0; k < 4000; ++k) {
    const double x = -1 + 2 * random.uniform(), y = -1 + 2 * random.uniform();
    const bool covered = on_teapot(x, y);
    bool settled = true;
    for (int d = 0; d < 8; ++d) {
      const double angle = d * std::acos(-1.0) / 4;
      settled = settled && on_teapot(x + 2 * kTolerance * std::cos(angle),
                                     y + 2 * kTolerance * std::sin(angle)) == covered;
    }
    if (!settled) {
      ++near_edge;
      continue;
    }
    BOOST_TEST(in_polygons(shadow, x, y) == covered, "at " << x << ", " << y);
    ++(covered ? inside : outside);
  }
  BOOST_TEST_MESSAGE("under the teapot " << inside << ", beside it " << outside
                                         << ", within twice the tolerance of its outline "
                                         << near_edge);
  BOOST_TEST(inside > 500);  // 541 at the sanitizers' coarser tolerance, 734 at the finer
  BOOST_TEST(outside > 500);
}

BOOST_AUTO_TEST_CASE(a_bad_patch_file_exits_2_naming_file_and_line_and_writes_nothing) {
  const auto dir = penumbra::test::scratch_dir("bezier-bad-cli");
  std::ofstream(dir / "bad.bpt") << "1\n3 3\n0 0 0\n0 1 x\n";
  std::ofstream(dir / "scene.json")
      << R"({"penumbra": 1, "objects": [{"name": "pot", "bezier_patches": "bad.bpt"}],
             "camera": {"eye": [3, 3, 3], "target": [0, 0, 0], "width": 8, "height": 8}})";
  const auto result = run_penumbra("raytrace '" + (dir / "scene.json").string() + "' -o '" +
                                   (dir / "x.png").string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("scene.json: objects[0].bezier_patches") != std::string::npos,
             result.err);
  BOOST_TEST(result.err.find("bad.bpt: line 4: \"x\" is not a finite number") != std::string::npos,
             result.err);
  BOOST_TEST(!std::filesystem::exists(dir / "x.png"));
}

BOOST_AUTO_TEST_SUITE_END()
