// The command line end to end: verbs, help, exit statuses, info, error reports.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
                           "radiosity", "basis", "relight", "serve", "sun"}) {
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
  BOOST_TEST(contains(result.out, "object chair/back (mesh"));
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

BOOST_AUTO_TEST_CASE(sun_lists_the_day_against_the_spa_sunrise_and_sunset) {
  // Golden, Colorado, 2003-10-17 at UTC-7: the NREL SPA report's worked example (Reda and
  // Andreas 2004, appendix A.5) gives sunrise 06:12:43 and sunset 17:20:19 local time,
  // when the centre is 0.8333 degrees below the horizon.
  const auto dir = penumbra::test::scratch_dir("cli-sun");
  const auto scene = dir / "golden.json";
  std::ofstream(scene) << R"({"penumbra": 1, "north_deg": 90, "lights": [{"name": "sun",
      "sun": {"latitude": 39.742476, "longitude": -105.1786, "elevation": 1830.14,
              "pressure": 820, "temperature": 11, "time": "2003-10-17T12:30:30-07:00"},
      "illuminance": 100000}]})";
  const auto result = run_penumbra("sun '" + scene.string() +
                                   "' --from 2003-10-17T06:00 --to 2003-10-17T18:00 --step 1h");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  std::istringstream lines(result.out);
  std::string line;
  std::getline(lines, line);
  BOOST_TEST(line == "time,azimuth_deg,elevation_deg,dx,dy,dz");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    rows.push_back(fields);
  }
  BOOST_TEST_REQUIRE(rows.size() == 13u);
  BOOST_TEST(rows.front()[0] == "2003-10-17T06:00:00-07:00");
  BOOST_TEST(rows.back()[0] == "2003-10-17T18:00:00-07:00");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double azimuth = std::stod(rows[k][1]), elevation = std::stod(rows[k][2]);
    // 06:00 is before sunrise and 18:00 after sunset; 07:00 to 17:00 the sun is up.
    const bool up = k >= 1 && k <= 11;
    BOOST_TEST((elevation > -0.8333) == up, rows[k][0]);
    // north_deg 90: north is -X and east +Y; the light travels away from the sun.
    const double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
    const double expected[3] = {std::cos(e) * std::cos(a), -std::cos(e) * std::sin(a),
                                -std::sin(e)};
    for (int i = 0; i < 3; ++i)
      BOOST_TEST(std::abs(std::stod(rows[k][3 + i]) - expected[i]) < 1e-9, rows[k][0]);
  }
  // A scene without a sun by place and time is an input error.
  BOOST_TEST(run_penumbra("sun fixtures/scenes/office.json").status == 2);
}

BOOST_AUTO_TEST_SUITE_END()
