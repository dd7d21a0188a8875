// The command line end to end: verbs, help, exit statuses, info, error reports.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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
                           "radiosity", "basis", "relight", "serve", "sun", "sun-hours"}) {
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

BOOST_AUTO_TEST_CASE(check_compares_a_curved_golden_exactly) {
  // A golden written with --joint-umbrae --exact holds each curved region in canonical exact
  // form (conics and algebraic corners): check recomputes with joint umbrae (the golden says
  // so) and finds it equal, also for the scene with its objects in reverse order; a changed
  // conic or corner is a difference (status 1, naming the face, light and region); a
  // golden without --exact is refused (status 2).
  const auto dir = penumbra::test::scratch_dir("cli-curved-golden");
  const auto golden = dir / "joint.json";
  const std::string scene = "fixtures/scenes/linear-joint-umbra.json";
  BOOST_TEST_REQUIRE(
      run_penumbra("shadows " + scene + " --joint-umbrae --exact -o '" + golden.string() + "'")
          .status == 0);
  auto result = run_penumbra("check " + scene + " --golden '" + golden.string() + "'");
  BOOST_TEST(result.status == 0, result.out + result.err);
  BOOST_TEST(contains(result.out, "equal to"));

  auto document = nlohmann::json::parse(penumbra::test::read_text(golden));
  BOOST_TEST(document.at("joint_umbrae") == true);
  const auto reversed = dir / "reversed.json";
  auto scene_json = nlohmann::json::parse(penumbra::test::read_text(scene));
  std::reverse(scene_json["objects"].begin(), scene_json["objects"].end());
  std::ofstream(reversed) << scene_json.dump();
  result = run_penumbra("check '" + reversed.string() + "' --golden '" + golden.string() + "'");
  BOOST_TEST(result.status == 0, result.out + result.err);

  nlohmann::json* joint_edge = nullptr;  // the umbra's edge on the joint conic
  std::string where;
  for (auto& entry : document["faces"])
    for (auto& shadow : entry["lights"])
      if (shadow["umbra"].contains("axes"))
        for (auto& edge : shadow["umbra"]["exact"][0]["outer"])
          if (edge["joint"] == true && !joint_edge) {
            joint_edge = &edge;
            where = entry["object"].get<std::string>() + " face " + entry["face"].dump() +
                    ", light " + shadow["light"].get<std::string>() + ": umbra differs";
          }
  BOOST_TEST_REQUIRE(joint_edge != nullptr);
  const nlohmann::json kept = *joint_edge;
  const auto changed = dir / "changed.json";
  for (int change = 0; change < 2; ++change) {
    *joint_edge = kept;
    if (change == 0)
      (*joint_edge)["conic"][5] = "1/3";
    else  // another corner: the same polynomial's next root, or another rational
      (*joint_edge)["from"]["s"] =
          (*joint_edge)["from"]["s"].is_string()
              ? nlohmann::json("1/7")
              : nlohmann::json{{"of", kept["from"]["s"]["of"]},
                               {"root", kept["from"]["s"]["root"].dump() == "0" ? 1 : 0}};
    std::ofstream(changed) << document.dump();
    result = run_penumbra("check " + scene + " --golden '" + changed.string() + "'");
    BOOST_TEST(result.status == 1, result.out + result.err);
    BOOST_TEST(contains(result.out, where), result.out);
  }

  const auto plain = dir / "plain.json";
  BOOST_TEST_REQUIRE(
      run_penumbra("shadows " + scene + " --joint-umbrae -o '" + plain.string() + "'").status == 0);
  result = run_penumbra("check " + scene + " --golden '" + plain.string() + "'");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(contains(result.err, "missing \"exact\" (write golden files with --exact)"),
             result.err);
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

BOOST_AUTO_TEST_CASE(sun_hours_writes_its_documents_and_answers_the_threshold) {
  using penumbra::test::csv_columns;
  using penumbra::test::read_text;
  const auto dir = penumbra::test::scratch_dir("cli-sun-hours");
  const std::string files = " -o '" + (dir / "h.json").string() + "' --report '" +
                            (dir / "h.csv").string() + "' --svg '" + (dir / "h.svg").string() +
                            "' --png '" + (dir / "h.png").string() + "' --png-width 300";
  const auto result = run_penumbra("sun-hours fixtures/scenes/sun-london.json --step 1h" + files);
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto document = nlohmann::json::parse(read_text(dir / "h.json"));
  BOOST_TEST(document.at("penumbra_sun_hours").get<int>() == 1);
  // 21 March in London: the sun is up from about 06:05 to 18:15 UTC, 12 hourly steps.
  BOOST_TEST(document.at("steps").at("sun_up").get<int>() == 12);
  BOOST_TEST(document.at("steps").at("count").get<int>() == 24);
  const auto csv = csv_columns(read_text(dir / "h.csv"));
  BOOST_TEST_REQUIRE(csv.at("face").size() == document.at("faces").size());
  for (std::size_t k = 0; k < csv.at("face").size(); ++k) {
    // Every face gets at least 0 h over all of it; the areas with more sun shrink.
    const double area = std::stod(csv.at("face_area")[k]);
    BOOST_TEST(std::stod(csv.at("area_ge_0h")[k]) == area, boost::test_tools::tolerance(1e-12));
    double parts = 0;
    for (const auto& part : document.at("faces")[k].at("hours"))
      parts += part.at("area").get<double>();
    BOOST_TEST(parts == area, boost::test_tools::tolerance(1e-9));
    for (int h = 1; csv.count("area_ge_" + std::to_string(h) + "h"); ++h)
      BOOST_TEST(std::stod(csv.at("area_ge_" + std::to_string(h) + "h")[k]) <=
                 std::stod(csv.at("area_ge_" + std::to_string(h - 1) + "h")[k]));
  }
  BOOST_TEST(contains(read_text(dir / "h.svg"), "hours of direct sun"));
  BOOST_TEST(penumbra::test::png_size(read_text(dir / "h.png")).first == 300u);

  // The threshold over the ground's faces is the CSV's column summed over them.
  const auto threshold = run_penumbra(
      "sun-hours fixtures/scenes/sun-london.json --step 1h --threshold 2h --region ground");
  BOOST_TEST_REQUIRE(threshold.status == 0, threshold.err);
  double ground = 0;
  for (std::size_t k = 0; k < csv.at("object").size(); ++k)
    if (csv.at("object")[k] == "ground") ground += std::stod(csv.at("area_ge_2h")[k]);
  std::ostringstream expected;
  expected << "region ground: " << std::setprecision(6) << ground << " m2";
  BOOST_TEST(contains(threshold.out, expected.str()), threshold.out);
  // Then one line per face of the region: the ground box's top face (3) is the garden.
  std::ostringstream top;
  top << "  ground face 3: " << std::setprecision(6) << std::stod(csv.at("area_ge_2h")[3]) << " m2";
  BOOST_TEST(csv.at("object")[3] == "ground");
  BOOST_TEST(contains(threshold.out, top.str()), threshold.out);
  // A plan polygon over the ground's extent, [-20, 20]^2: the same top face, and the faces
  // facing up inside it (the roofs of the tower and the pavilion).
  const auto plan = run_penumbra(
      "sun-hours fixtures/scenes/sun-london.json --step 1h --threshold 2h --region "
      "'-20,-20 20,-20 20,20 -20,20'");
  BOOST_TEST_REQUIRE(plan.status == 0, plan.err);
  BOOST_TEST(contains(plan.out, "region plan polygon of 4 points: "), plan.out);
  BOOST_TEST(contains(plan.out, top.str()), plan.out);
  BOOST_TEST(contains(plan.out, "  tower face 3: "), plan.out);
  BOOST_TEST(!contains(plan.out, "ground face 0"), plan.out);  // vertical: no plan area

  // Bad input: exit 2, nothing written.
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (const char* bad :
       {"--date 2026-13-01", "--step 0min", "--threshold 2h", "--region ground",
        "--date 2026-03-22 --to 2026-03-21", "--threshold 2h --region nothing", "--light moon",
        "--threshold 2h --region '0,0 1,1 0,1 1,0'", "--threshold 2h --region '0,0 1,1'"}) {
    const auto failed =
        run_penumbra(std::string("sun-hours fixtures/scenes/sun-london.json ") + bad + files);
    BOOST_TEST(failed.status == 2, bad);
    BOOST_TEST(std::filesystem::is_empty(dir), bad);
  }
  BOOST_TEST(run_penumbra("sun-hours fixtures/scenes/office.json").status == 2);
}

BOOST_AUTO_TEST_CASE(shadow_diagram_holds_each_time_as_the_scene_at_that_time) {
  using penumbra::test::read_text;
  const auto dir = penumbra::test::scratch_dir("cli-diagram");
  const std::string out = (dir / "d.json").string(), svg = (dir / "d.svg").string();
  // 04:00 is before sunrise in London in March: skipped and said so.
  const auto result = run_penumbra(
      "shadows fixtures/scenes/sun-london.json --times "
      "2026-03-21T04:00,2026-03-21T12:00,4h -o '" +
      out + "' --svg '" + svg + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(contains(result.err, "below the horizon at 2026-03-21T04:00:00+00:00"));
  const auto diagram = nlohmann::json::parse(read_text(out));
  BOOST_TEST(diagram.at("skipped").size() == 1u);
  BOOST_TEST_REQUIRE(diagram.at("times").size() == 2u);
  // Each time's shadows are those of the scene with its sun set to that time (the scene
  // loader's one-shot solar position against the study's interpolating solver: areas agree
  // to 1e-6 relative).
  std::string scene = read_text(penumbra::test::fixture("scenes/sun-london.json"));
  const std::string noon = "2026-03-21T12:00:00+00:00";
  for (const auto& [k, time] :
       {std::pair{0, "2026-03-21T08:00:00+00:00"}, std::pair{1, noon.c_str()}}) {
    const auto& entry = diagram.at("times")[k];
    BOOST_TEST(entry.at("time").get<std::string>() == time);
    std::string moved = scene;
    moved.replace(moved.find(noon), noon.size(), time);
    const auto path = dir / ("scene" + std::to_string(k) + ".json");
    std::ofstream(path) << moved;
    const auto single = run_penumbra("shadows '" + path.string() + "'");
    BOOST_TEST_REQUIRE(single.status == 0, single.err);
    const auto expected = nlohmann::json::parse(single.out).at("faces");
    const auto& faces = entry.at("shadows").at("faces");
    BOOST_TEST_REQUIRE(faces.size() == expected.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const double a = faces[f].at("lights")[0].at("shadow").at("area").get<double>();
      const double b = expected[f].at("lights")[0].at("shadow").at("area").get<double>();
      BOOST_TEST(std::abs(a - b) <= 1e-6 * std::max(1.0, b), time << " face " << f);
    }
  }
  const std::string drawing = read_text(svg);
  BOOST_TEST(contains(drawing, "<g class=\"time-2026-03-21T08-00-00-00-00\">"));
  BOOST_TEST(contains(drawing, "<g class=\"time-2026-03-21T12-00-00-00-00\">"));
  // One time only: --dxf, --report and --loops are refused with --times; bad times too.
  for (const char* bad : {"--times 2026-03-21T12:00 --dxf x.dxf", "--times 2026-03-21T25:00",
                          "--times 2026-03-21T12:00,2026-03-21T08:00,1h"})
    BOOST_TEST(
        run_penumbra(std::string("shadows fixtures/scenes/sun-london.json ") + bad).status == 2,
        bad);
}

BOOST_AUTO_TEST_SUITE_END()
