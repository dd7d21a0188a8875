#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/fixtures.h"

namespace {

using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

// reads a CSV into rows of column name -> text (simple fields: no quotes).
std::vector<std::map<std::string, std::string>> read_csv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream head(line);
  for (std::string name; std::getline(head, name, ',');) header.push_back(name);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::map<std::string, std::string> row;
    std::stringstream fields(line);
    std::string field;
    for (const std::string& name : header) {
      std::getline(fields, field, ',');
      row[name] = field;
    }
    rows.push_back(row);
  }
  return rows;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// CIE 171 test 5.2 (E = 9000 / (9 + rho^2)^2 around (2, 2), derived in
// scene_illuminance_test.cpp).
double cie_field(double x, double y) {
  const double rho2 = (x - 2) * (x - 2) + (y - 2) * (y - 2);
  return 9000 / ((9 + rho2) * (9 + rho2));
}

const std::string scene = fixture("scenes/illuminance-cie-5-2.json").string();

}  // namespace

BOOST_AUTO_TEST_SUITE(illuminance_cli)

// Columns are found by name: here in another order, with an extra column.
BOOST_AUTO_TEST_CASE(points_file_gives_e_per_point_and_per_light) {
  const auto dir = scratch_dir("illuminance-points");
  write(dir / "pts.csv",
        "label,nz,x,y,z,nx,ny\ncentre,1,2,2,0,0,0\ncorner,1,0,0,0,0,0\nedge,1, 4,2,0,0,0\n"
        "tilted,0.7071,2,2,0,0.7071,0\n");
  const auto result =
      run_penumbra("illuminance '" + scene + "' --points '" + (dir / "pts.csv").string() +
                   "' -o '" + (dir / "values.csv").string() + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto rows = read_csv(read_text(dir / "values.csv"));
  BOOST_TEST_REQUIRE(rows.size() == 4u);
  const double expected[3] = {cie_field(2, 2), cie_field(0, 0), cie_field(4, 2)};
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(std::stod(rows[k].at("E")) == expected[k], boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::stod(rows[k].at("E[cie]")) == expected[k], boost::test_tools::tolerance(1e-12));
  }
  // A normal tilted 45 degrees toward +x under the lamp: cos(alpha) = 1/sqrt(2), I = 1000 cd
  // at r = 3 (the normal is normalised from its four-decimal form).
  BOOST_TEST(std::stod(rows[3].at("E")) == 1000 / std::sqrt(2.0) / 9,
             boost::test_tools::tolerance(1e-9));
  BOOST_TEST(rows[0].at("inside").empty());
}

BOOST_AUTO_TEST_CASE(bad_points_files_exit_2_and_write_nothing) {
  const auto dir = scratch_dir("illuminance-bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x,y,z,nx,ny\n1,1,0,0,0\n", "missing column \"nz\""},
      {"x,y,z,nx,ny,nz\n1,1,0,0,0,1\n1,nan,0,0,0,1\n", "line 3, column y"},
      {"x,y,z,nx,ny,nz\n1,1,0,0,0,1\n1,abc,0,0,0,1\n", "line 3, column y"},
      {"x,y,z,nx,ny,nz\n1,1,0,0,0,0\n", "zero vector"},
      {"x,y,z,nx,ny,nz\n1,1,0,0,0,2\n", "unit vector"},
      {"x,y,z,nx,ny,nz\n1,1,0,0,1\n", "expected 6 fields"},
  };
  for (const auto& [text, message] : cases) {
    write(dir / "pts.csv", text);
    const auto result =
        run_penumbra("illuminance '" + scene + "' --points '" + (dir / "pts.csv").string() +
                     "' -o '" + (dir / "out.csv").string() + "'");
    BOOST_TEST(result.status == 2);
    BOOST_TEST(result.err.find(message) != std::string::npos, result.err);
    BOOST_TEST(result.err.find("pts.csv") != std::string::npos, result.err);
    BOOST_TEST(!std::filesystem::exists(dir / "out.csv"));
  }
  BOOST_TEST(run_penumbra("illuminance '" + scene + "'").status == 2);  // neither mode
  BOOST_TEST(run_penumbra("illuminance '" + scene + "' --workplane 0").status == 2);  // no spacing
}

// The work plane of the CIE scene on 0.5 m cells: statistics against the formula at the
// cell centres, the grid CSV by column name, and an isolux SVG.
BOOST_AUTO_TEST_CASE(workplane_reports_statistics_and_writes_grid_and_svg) {
  const auto dir = scratch_dir("illuminance-workplane");
  const auto result =
      run_penumbra("illuminance '" + scene + "' --workplane 0 --spacing 0.5 --region 0,0,4,4 -o '" +
                   (dir / "grid.csv").string() + "' --svg '" + (dir / "iso.svg").string() + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  double minimum = 1e300, maximum = 0, sum = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double e = cie_field(0.25 + 0.5 * i, 0.25 + 0.5 * j);
      minimum = std::min(minimum, e);
      maximum = std::max(maximum, e);
      sum += e;
    }
  const auto rows = read_csv(read_text(dir / "grid.csv"));
  BOOST_TEST_REQUIRE(rows.size() == 64u);
  for (const auto& row : rows)
    BOOST_TEST(std::stod(row.at("E")) == cie_field(std::stod(row.at("x")), std::stod(row.at("y"))),
               boost::test_tools::tolerance(1e-12));
  // "E min <min> lx, average <avg> lx, max <max> lx, uniformity U0 = Emin/Eavg = <u0>"
  const std::string& out = result.out;
  const auto number_after = [&](const std::string& key) {
    const std::size_t at = out.find(key);
    BOOST_TEST_REQUIRE(at != std::string::npos, out);
    return std::stod(out.substr(at + key.size()));
  };
  BOOST_TEST(number_after("E min ") == minimum, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(number_after("average ") == sum / 64, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(number_after("max ") == maximum, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(number_after("Emin/Eavg = ") == minimum / (sum / 64),
             boost::test_tools::tolerance(1e-5));
  const std::string svg = read_text(dir / "iso.svg");
  BOOST_TEST(svg.find("<polyline") != std::string::npos);
  BOOST_TEST(svg.find("floor") != std::string::npos);
}

// The default scene: the demo's command works and reports its statistics.
BOOST_AUTO_TEST_CASE(default_scene_workplane) {
  const auto dir = scratch_dir("illuminance-office");
  const auto result =
      run_penumbra("illuminance '" + fixture("scenes/office.json").string() +
                   "' --workplane 0.75 --spacing 0.25 -o '" + (dir / "grid.csv").string() +
                   "' --svg '" + (dir / "iso.svg").string() + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(result.out.find("uniformity U0") != std::string::npos);
  const auto rows = read_csv(read_text(dir / "grid.csv"));
  BOOST_TEST(rows.size() > 100u);
  BOOST_TEST(rows.front().count("E[tube]") == 1u);
  BOOST_TEST(rows.front().count("E[sun]") == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
