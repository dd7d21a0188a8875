// The command line end to end: verbs, help, exit statuses, info, error reports.

#include <boost/test/unit_test.hpp>

#include <fstream>

#include "support/fixtures.h"

using penumbra::test::run_penumbra;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli)

BOOST_AUTO_TEST_CASE(help_lists_every_verb_of_the_design) {
  const auto result = run_penumbra("--help");
  BOOST_TEST(result.status == 0);
  for (const char* verb : {"info", "shadows", "check", "illuminance", "render", "raytrace", "lid",
                           "radiosity", "basis", "relight", "serve"}) {
    BOOST_TEST(contains(result.out, std::string("  ") + verb), verb);
    BOOST_TEST(run_penumbra(std::string(verb) + " --help").status == 0, verb);
  }
}

BOOST_AUTO_TEST_CASE(usage_errors_exit_with_status_2) {
  BOOST_TEST(run_penumbra("").status == 2);
  BOOST_TEST(run_penumbra("frobnicate").status == 2);
  BOOST_TEST(run_penumbra("info").status == 2);
}

BOOST_AUTO_TEST_CASE(info_prints_counts_and_exact_planes) {
  const auto result = run_penumbra("info fixtures/scenes/every-kind.json");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  // Counts: floor 8 + desk 8 + panel 3 + seat 8 + back 8 + tetra 4 + ball 26 vertices;
  // faces 6 + 6 + 2 + 6 + 6 + 4 + ball's; lights 4, materials 2.
  BOOST_TEST(contains(result.out, "objects 7, faces "));
  BOOST_TEST(contains(result.out, "vertices 65, lights 4, materials 2"));
  // The floor's top face (z = 0, canonical index 3) with its exact plane.
  BOOST_TEST(contains(result.out, "object floor (box, material white): 6 faces, 8 vertices"));
  BOOST_TEST(contains(result.out, "  face 3: 4 vertices, plane [0, 0, 1, 0]"));
  // The tetrahedron's slanted face x + y + z = 1, scaled to unit largest component.
  BOOST_TEST(contains(result.out, "plane [1, 1, 1, -1]"));
  BOOST_TEST(contains(result.out, "object chair#1 (mesh"));
  BOOST_TEST(contains(result.out, "light tube (linear)"));
}

BOOST_AUTO_TEST_CASE(bad_scene_reports_file_and_path_and_exits_2) {
  const auto dir = penumbra::test::scratch_dir("cli-bad");
  const auto scene = dir / "bad.json";
  std::ofstream(scene)
      << R"({"penumbra": 1, "lights": [{"linear": [[0,0,1],[0,0,1]], "candela_per_metre": 5}]})";
  const auto result = run_penumbra("info '" + scene.string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.out.empty());
  BOOST_TEST(
      contains(result.err,
               scene.string() + ": lights[0].linear: a linear source must not have zero length"));
}

BOOST_AUTO_TEST_SUITE_END()
