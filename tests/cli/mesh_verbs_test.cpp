// Every verb on a scene with real models (issue #14): the L-shaped courtyard building (a
// closed non-convex solid) and the open canopy, under a point lamp, a tube and the sun.
// Each verb runs to completion and writes its file; the shadow document names the parts'
// faces once with {"outer", "holes"} boundaries, and `check` accepts it as a golden file. (The
// values themselves are checked by the oracle tests: tests/shadow/mesh_oracle_test.cpp.)

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::run_penumbra;

namespace {

std::filesystem::path mesh_scene() {
  const auto dir = penumbra::test::scratch_dir("mesh-verbs");
  nlohmann::json scene = {
      {"penumbra", 1},
      {"objects",
       {{{"name", "ground"}, {"box", {{"min", {-10, -10, -1}}, {"max", {20, 20, 0}}}}},
        {{"name", "block"}, {"mesh", fixture("meshes/l-courtyard.obj").string()}},
        {{"name", "canopy"},
         {"mesh", fixture("meshes/canopy.obj").string()},
         {"transform", {1, 0, 0, 14, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}}}},
      {"lights",
       {{{"name", "lamp"}, {"point", {6, 6, 4}}, {"candela", 800}},
        {{"name", "tube"}, {"linear", {{5, 7, 5}, {7, 7, 5}}}, {"candela_per_metre", 200}},
        {{"name", "sun"}, {"directional", {-0.5, -0.3, -1}}, {"illuminance", 80000}}}},
      {"camera", {{"eye", {-8, -8, 10}}, {"target", {5, 5, 0}}, {"width", 80}, {"height", 60}}}};
  std::ofstream(dir / "scene.json") << scene.dump();
  return dir / "scene.json";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_verbs)

BOOST_AUTO_TEST_CASE(every_verb_runs_on_real_models) {
  const auto scene = mesh_scene();
  const auto dir = scene.parent_path();
  const std::string s = "'" + scene.string() + "'";
  const auto out = [&](const std::string& name) { return "'" + (dir / name).string() + "'"; };

  const auto info = run_penumbra("info " + s);
  BOOST_TEST_REQUIRE(info.status == 0, info.err);
  BOOST_TEST(info.out.find("object block (mesh") != std::string::npos, info.out);

  const auto shadows = run_penumbra("shadows " + s + " --exact -o " + out("loops.json") +
                                    " --svg " + out("loops.svg") + " --dxf " + out("loops.dxf") +
                                    " --report " + out("areas.csv"));
  BOOST_TEST_REQUIRE(shadows.status == 0, shadows.err);
  const nlohmann::json document = nlohmann::json::parse(std::ifstream(dir / "loops.json"));
  std::size_t block_faces = 0, with_holes_form = 0;
  for (const nlohmann::json& face : document.at("faces")) {
    if (face.at("object") != "block") continue;
    ++block_faces;
    with_holes_form += face.at("boundary").is_object();
    BOOST_TEST(face.at("lights").size() == 3u);
  }
  BOOST_TEST(block_faces == 8u);  // the L block's 8 faces, each once
  BOOST_TEST(with_holes_form == block_faces);
  // check agrees with the document it wrote (exact golden comparison).
  const auto check = run_penumbra("check " + s + " --golden " + out("loops.json"));
  BOOST_TEST(check.status == 0, check.out + check.err);

  std::ofstream(dir / "points.csv") << "x,y,z,nx,ny,nz\n6,6,0,0,0,1\n";
  const auto illuminance = run_penumbra("illuminance " + s + " --points " + out("points.csv") +
                                        " -o " + out("values.csv"));
  BOOST_TEST(illuminance.status == 0, illuminance.err);
  const auto render = run_penumbra("render " + s + " -o " + out("render.png"));
  BOOST_TEST(render.status == 0, render.err);
  const auto raytrace = run_penumbra("raytrace " + s + " -o " + out("raytrace.png"));
  BOOST_TEST(raytrace.status == 0, raytrace.err);
  const auto radiosity =
      run_penumbra("radiosity " + s + " --patch-size 2 --rays 64 -o " + out("patches.csv"));
  BOOST_TEST(radiosity.status == 0, radiosity.err);
  for (const char* file : {"loops.svg", "loops.dxf", "areas.csv", "values.csv", "render.png",
                           "raytrace.png", "patches.csv"})
    BOOST_TEST(std::filesystem::file_size(dir / file) > 0u, file);

  // basis and relight solve on radiosity's patches (the receiving sides of the pieces). The
  // lamp is isotropic, so its degree-2 series is exact; the tube and the sun are one column
  // each: relit at the file's lights, every patch's E_direct and E are radiosity's, to the
  // float storage of the .pbl (measured 1e-7 relative).
  const auto basis =
      run_penumbra("basis " + s + " --degree 2 --patch-size 2 --rays 64 -o " + out("scene.pbl"));
  BOOST_TEST_REQUIRE(basis.status == 0, basis.err);
  const auto relight =
      run_penumbra("relight " + out("scene.pbl") + " --patches " + out("relit.csv"));
  BOOST_TEST_REQUIRE(relight.status == 0, relight.err);
  const auto relit = penumbra::test::csv_columns(penumbra::test::read_text(dir / "relit.csv"));
  const auto solved = penumbra::test::csv_columns(penumbra::test::read_text(dir / "patches.csv"));
  BOOST_TEST_REQUIRE(relit.at("E").size() == solved.at("E").size());
  BOOST_TEST(relit.at("E").size() > 100u);
  BOOST_TEST(relit.at("object") == solved.at("object"), boost::test_tools::per_element());
  for (const char* column : {"E_direct", "E"})
    for (std::size_t i = 0; i < relit.at(column).size(); ++i) {
      const double a = std::stod(relit.at(column)[i]), b = std::stod(solved.at(column)[i]);
      BOOST_TEST(std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(b)), column << " row " << i);
    }
}

BOOST_AUTO_TEST_CASE(a_bad_model_writes_nothing_and_exits_2) {
  const auto dir = penumbra::test::scratch_dir("mesh-verbs-bad");
  std::ofstream(dir / "nan.obj") << "o bad\nv nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "scene.json")
      << R"({"penumbra": 1, "objects": [{"name": "m", "mesh": "nan.obj"}]})";
  const auto result = run_penumbra("shadows '" + (dir / "scene.json").string() + "' -o '" +
                                   (dir / "out.json").string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("scene.json: objects[0].mesh: ") != std::string::npos, result.err);
  BOOST_TEST(result.err.find("part bad: mesh 0, vertex 0: a coordinate is not finite") !=
                 std::string::npos,
             result.err);
  BOOST_TEST(!std::filesystem::exists(dir / "out.json"));
}

BOOST_AUTO_TEST_CASE(a_tube_with_an_end_in_the_plane_of_a_flat_occluder_is_refused) {
  // The tube's end (0.5, 0, 3) lies in the card's plane y = 0, and the card shadows the
  // floor from the other end: no tangent vertices (docs/linear-shadows.md). Exit 2 with the
  // light named, no file; before, an unchecked assertion crashed here.
  const auto dir = penumbra::test::scratch_dir("mesh-verbs-flat-end");
  std::ofstream(dir / "scene.json") << R"({"penumbra": 1, "objects": [
      {"name": "floor", "box": {"min": [-5, -5, -1], "max": [5, 5, 0]}},
      {"name": "card", "polygon": [[0, 0, 1], [1, 0, 1], [1, 0, 2], [0, 0, 2]]}],
    "lights": [{"name": "tube", "linear": [[0.5, 0, 3], [0.5, 1, 3]], "candela_per_metre": 100}]})";
  const auto result = run_penumbra("shadows '" + (dir / "scene.json").string() + "' -o '" +
                                   (dir / "out.json").string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("lights[0]: the linear source 'tube'") != std::string::npos,
             result.err);
  BOOST_TEST(!std::filesystem::exists(dir / "out.json"));
}

BOOST_AUTO_TEST_SUITE_END()
