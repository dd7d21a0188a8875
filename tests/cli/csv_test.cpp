// Every CSV a verb writes, read back by an RFC 4180 reader written here (quoted fields,
// doubled quotes, separators and line breaks inside quotes): object and light names with a
// comma, a quote and non-ASCII letters round-trip, the header names the columns, and every
// number reads back as the double that was written.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "penumbra/base/csv.h"
#include "support/fixtures.h"

using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {

using Table = std::vector<std::vector<std::string>>;

// parses CSV text (RFC 4180) into rows of fields.
Table parse_csv(const std::string& text) {
  Table rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, field_started = false;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (quoted) {
      if (c == '"' && k + 1 < text.size() && text[k + 1] == '"') {
        field += '"';
        ++k;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && !field_started) {
      quoted = field_started = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
      field_started = false;
    } else if (c == '\n') {
      row.push_back(field);
      rows.push_back(row);
      row.clear();
      field.clear();
      field_started = false;
    } else {
      field += c;
      field_started = true;
    }
  }
  BOOST_TEST(!quoted);
  BOOST_TEST((row.empty() && field.empty()));  // the last row ends with a line break
  return rows;
}

// returns the values of column name in table (the header is the first row).
std::vector<std::string> column(const Table& table, const std::string& name) {
  const auto& header = table.at(0);
  const auto at = std::find(header.begin(), header.end(), name);
  BOOST_TEST_REQUIRE((at != header.end()), name);
  std::vector<std::string> values;
  for (std::size_t r = 1; r < table.size(); ++r) {
    BOOST_TEST_REQUIRE(table[r].size() == header.size());
    values.push_back(table[r][static_cast<std::size_t>(at - header.begin())]);
  }
  return values;
}

// The awkward names: a comma, a doubled quote, non-ASCII letters (UTF-8), a space.
const std::string floor_name = "floor, north";
const std::string cube_name = "cube \"A\"";
const std::string wall_name = "Wand – Süd";
const std::string lamp_name = "lamp,1 \"warm\"";

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\\\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(csv)

BOOST_AUTO_TEST_CASE(names_round_trip_through_every_verb_that_writes_csv) {
  const auto dir = scratch_dir("csv-names");
  const auto scene = dir / "awkward.json";
  {
    std::ofstream out(scene);
    out << R"({"penumbra": 1,
      "materials": {"grey": {"reflectance": 0.5}},
      "objects": [
        {"name": )"
        << json_string(floor_name)
        << R"(, "box": {"min": [0, 0, -0.1], "max": [4, 4, 0]}, "material": "grey"},
        {"name": )"
        << json_string(cube_name)
        << R"(, "box": {"min": [1, 1, 0], "max": [2, 2, 1]}, "material": "grey"},
        {"name": )"
        << json_string(wall_name)
        << R"(, "box": {"min": [0, 4, 0], "max": [4, 4.1, 2]}, "material": "grey"}],
      "lights": [{"name": )"
        << json_string(lamp_name) << R"(, "point": [3, 3, 2.5], "candela": 200}],
      "camera": {"eye": [5, -2, 3], "target": [2, 2, 0.5], "up": [0, 0, 1], "fov_deg": 60,
                 "width": 32, "height": 24}})";
  }
  {
    std::ofstream points(dir / "points.csv");
    points << "x,y,z,nx,ny,nz\n0.5,0.5,0,0,0,1\n1.5,1.5,0.5,0,0,1\n2,4,1,0,-1,0\n";
  }
  const std::string s = " '" + scene.string() + "'";
  const auto run = [&](const std::string& arguments) {
    const auto result = run_penumbra(arguments);
    BOOST_TEST_REQUIRE(result.status == 0, arguments + ": " + result.err);
  };
  run("shadows" + s + " --report " + (dir / "areas.csv").string());
  run("illuminance" + s + " --points " + (dir / "points.csv").string() + " -o " +
      (dir / "values.csv").string());
  run("illuminance" + s + " --workplane 0.5 --spacing 0.5 -o " + (dir / "plane.csv").string());
  run("render" + s + " -o " + (dir / "r.png").string() + " --values " +
      (dir / "render.csv").string());
  run("raytrace" + s + " -o " + (dir / "t.png").string() + " --values " +
      (dir / "trace.csv").string());
  run("radiosity" + s + " --patch-size 1 --rays 16 -o " + (dir / "patches.csv").string());
  run("basis" + s + " --degree 1 --patch-size 1 --rays 16 -o " + (dir / "b.pbl").string());
  run("relight " + (dir / "b.pbl").string() + " --patches " + (dir / "relit.csv").string());

  const std::set<std::string> objects{floor_name, cube_name, wall_name};
  const auto names_in = [&](const std::string& file, const std::string& name) {
    std::set<std::string> seen;
    for (const std::string& value : column(parse_csv(read_text(dir / file)), name))
      if (!value.empty()) seen.insert(value);
    return seen;
  };
  // shadows --report: every object's faces, the lamp, and the cube among the occluders.
  BOOST_TEST((names_in("areas.csv", "object") == objects));
  BOOST_TEST((names_in("areas.csv", "light") == std::set<std::string>{lamp_name}));
  BOOST_TEST(names_in("areas.csv", "occluders").count(cube_name) == 1u);
  // illuminance: one column per light, named E[<light>]; the point inside the cube named.
  const Table values = parse_csv(read_text(dir / "values.csv"));
  BOOST_TEST(values.at(0).at(7) == "E[" + lamp_name + "]");
  BOOST_TEST(column(values, "inside").at(1) == cube_name);
  BOOST_TEST(parse_csv(read_text(dir / "plane.csv")).at(0).at(7) == "E[" + lamp_name + "]");
  // the images' pixels and the patches name the objects they show.
  for (const char* file : {"render.csv", "trace.csv", "patches.csv", "relit.csv"})
    BOOST_TEST((names_in(file, "object") == objects), file);
}

BOOST_AUTO_TEST_CASE(numbers_are_written_in_the_shortest_form_that_reads_back_exactly) {
  // Random doubles of every magnitude (fixed seed: the same draws on every run).
  std::mt19937_64 engine(20261201);
  std::ostringstream out;
  penumbra::CsvWriter writer(out, {"value"});
  std::vector<double> written;
  for (int k = 0; k < 10000; ++k) {
    std::uint64_t bits = engine();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value)) continue;
    written.push_back(value);
    writer.number(value).end_row();
  }
  for (double value : {0.1, 1.0 / 3, 1e-300, -0.0, 5e-324, 123456789.0})
    written.push_back(value), writer.number(value).end_row();
  const Table table = parse_csv(out.str());
  const auto texts = column(table, "value");
  BOOST_TEST_REQUIRE(texts.size() == written.size());
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < texts.size(); ++k) {
    const double read = std::strtod(texts[k].c_str(), nullptr);
    wrong += std::memcmp(&read, &written[k], sizeof read) != 0;
  }
  BOOST_TEST(wrong == 0u);
  BOOST_TEST(texts.at(texts.size() - 6) == "0.1");
  BOOST_TEST(texts.at(texts.size() - 1) == "123456789");
}

BOOST_AUTO_TEST_CASE(fields_are_quoted_only_when_they_must_be) {
  BOOST_TEST(penumbra::csv_field("plain name") == "plain name");
  BOOST_TEST(penumbra::csv_field("a,b") == "\"a,b\"");
  BOOST_TEST(penumbra::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  BOOST_TEST(penumbra::csv_field("two\nlines") == "\"two\nlines\"");
  BOOST_TEST(penumbra::csv_field("Süd") == "Süd");
}

BOOST_AUTO_TEST_SUITE_END()
