// `penumbra check` on the golden files of fixtures/golden/ (regression data: the
// correctness evidence is the oracle and the hand derivations), and its exit
// statuses: 0 equal, 1 different with a readable line per face, 2 bad input.

#include <boost/test/unit_test.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "support/fixtures.h"

using namespace penumbra::test;

namespace {

const char* const goldens[] = {"every-kind",
                               "shadow-cube-point",
                               "shadow-cube-sun",
                               "shadow-touching",
                               "shadow-cutting",
                               "shadow-behind-light",
                               "shadow-shared-face",
                               "shadow-light-in-plane",
                               "shadow-sun-parallel",
                               "shadow-abutting",
                               "shadow-collinear-contour",
                               "shadow-light-inside",
                               "linear-fig5",
                               "linear-fig6",
                               "linear-degenerate",
                               "linear-joint",
                               "mesh-canopy",
                               "mesh-courtyard",
                               "mesh-noisy",
                               "mesh-staircase",
                               "mesh-through-hole",
                               "mesh-window",
                               "office"};

std::string check_command(const std::string& scene, const std::string& golden) {
  return "check '" + scene + "' --golden '" + golden + "'";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(golden)

BOOST_AUTO_TEST_CASE(every_golden_file_checks_equal) {
  for (const char* name : goldens) {
    const auto result =
        run_penumbra(check_command(fixture(std::string("scenes/") + name + ".json"),
                                   fixture(std::string("golden/") + name + ".json")));
    BOOST_TEST(result.status == 0, name << ": " << result.out << result.err);
  }
}

BOOST_AUTO_TEST_CASE(a_moved_vertex_is_reported_per_face_with_status_1) {
  const auto golden_path = fixture("golden/shadow-cube-point.json");
  nlohmann::json golden = nlohmann::json::parse(read_text(golden_path));
  // Move one exact shadow vertex of the floor's top by the smallest step a string shows.
  bool moved = false;
  for (auto& face : golden["faces"])
    for (auto& light : face["lights"])
      if (!moved && face["object"] == "floor" && !light["faces_away"].get<bool>() &&
          !light["shadow"]["polygons"].empty()) {
        auto& x = light["shadow"]["polygons"][0]["exact"]["outer"][0][0];
        x = x.get<std::string>() + "000001/1000000";
        moved = true;
      }
  BOOST_TEST_REQUIRE(moved);
  const auto dir = scratch_dir("golden-moved");
  std::ofstream(dir / "moved.json") << golden.dump(1);
  const auto result = run_penumbra(
      check_command(fixture("scenes/shadow-cube-point.json"), (dir / "moved.json").string()));
  BOOST_TEST(result.status == 1);
  BOOST_TEST(result.out.find("floor face") != std::string::npos, result.out);
  BOOST_TEST(result.out.find("shadow differs") != std::string::npos, result.out);
}

BOOST_AUTO_TEST_CASE(bad_golden_files_exit_with_status_2) {
  const auto dir = scratch_dir("golden-bad");
  std::ofstream(dir / "broken.json") << "{\"penumbra_shadows\": 1, \"faces\": [";
  std::ofstream(dir / "other.json") << "{\"penumbra\": 1}";
  const auto scene = fixture("scenes/shadow-cube-point.json").string();
  BOOST_TEST(run_penumbra(check_command(scene, (dir / "broken.json").string())).status == 2);
  BOOST_TEST(run_penumbra(check_command(scene, (dir / "other.json").string())).status == 2);
  BOOST_TEST(run_penumbra(check_command(scene, (dir / "missing.json").string())).status == 2);
  // A golden file written without --exact cannot be compared exactly.
  const auto inexact = dir / "inexact.json";
  BOOST_TEST_REQUIRE(run_penumbra("shadows '" + scene + "' -o '" + inexact.string() + "'").status ==
                     0);
  const auto result = run_penumbra(check_command(scene, inexact.string()));
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.err.find("--exact") != std::string::npos, result.err);
}

BOOST_AUTO_TEST_CASE(shadows_reports_bad_input_with_status_2_and_writes_nothing) {
  const auto dir = scratch_dir("shadows-bad");
  const auto scene = fixture("scenes/shadow-cube-point.json").string();
  const auto out = dir / "loops.json";
  BOOST_TEST(
      run_penumbra("shadows '" + scene + "' --light nobody -o '" + out.string() + "'").status == 2);
  BOOST_TEST(
      run_penumbra("shadows '" + scene + "' --view sideways -o '" + out.string() + "'").status ==
      2);
  BOOST_TEST(run_penumbra("shadows '" + scene + "' --view camera --svg '" +
                          (dir / "a.svg").string() + "' -o '" + out.string() + "'")
                 .status == 2);
  // A tube passing through a box that shadows the floor is refused, naming the light.
  const auto through = dir / "through.json";
  std::ofstream(through) << R"({"penumbra": 1, "objects": [
      {"name": "floor", "box": {"min": [-4, -4, -1], "max": [4, 4, 0]}},
      {"name": "block", "box": {"min": [0, 0, 1], "max": [1, 1, 2]}}],
    "lights": [{"name": "tube", "linear": [[-1, 0.5, 1.5], [2, 0.5, 1.5]], "candela_per_metre": 10}]})";
  const auto refused = run_penumbra("shadows '" + through.string() + "' -o '" + out.string() + "'");
  BOOST_TEST(refused.status == 2);
  BOOST_TEST(refused.err.find("lights[0]: the linear source 'tube' touches or passes through") !=
                 std::string::npos,
             refused.err);
  BOOST_TEST(!std::filesystem::exists(out));
}

BOOST_AUTO_TEST_SUITE_END()
