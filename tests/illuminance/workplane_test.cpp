#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "penumbra/illuminance/isolux.h"
#include "penumbra/illuminance/workplane.h"
#include "penumbra/io/isolux_svg.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

namespace {

using namespace penumbra;
using namespace penumbra::illuminance;

// The CIE 171 test 5.2 field, E = 9000 / (9 + rho^2)^2 around (2, 2) on z = 0.
double cie_field(double x, double y) {
  const double rho2 = (x - 2) * (x - 2) + (y - 2) * (y - 2);
  return 9000 / ((9 + rho2) * (9 + rho2));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(workplane)

BOOST_AUTO_TEST_CASE(grid_cells_are_no_wider_than_the_spacing_and_points_are_centres) {
  const WorkplaneGrid grid = make_workplane_grid(0.75, 0.1, {-0.1, 0, 6, 4.1});
  BOOST_TEST(grid.columns == 61u);  // 6.1 / 0.1, despite the quotient rounding to 60.99...
  BOOST_TEST(grid.rows == 41u);
  const WorkplaneGrid coarse = make_workplane_grid(0, 0.3, {0, 0, 1, 1});
  BOOST_TEST(coarse.columns == 4u);  // 1 / 0.3 = 3.33: four cells of 0.25
  BOOST_TEST(coarse.cell_width == 0.25);
  const Vec3d first = coarse.point(0), last = coarse.point(coarse.size() - 1);
  BOOST_TEST(first[0] == 0.125);
  BOOST_TEST(last[1] == 0.875);
  BOOST_TEST(first[2] == 0.0);
  BOOST_CHECK_THROW(make_workplane_grid(0, 0, {0, 0, 1, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(make_workplane_grid(0, 0.1, {1, 0, 0, 1}), std::invalid_argument);
}

// Statistics of the CIE field on a 0.5 m grid, against the formula at the same centres;
// a box standing through the plane removes the centres inside it from the statistics.
BOOST_AUTO_TEST_CASE(statistics_match_the_formula_and_skip_points_inside_objects) {
  const Scene scene = parse_scene(
      R"({"penumbra": 1, "objects": [{"name": "post", "box": {"min": [3.1, 3.1, -1], "max": [3.9, 3.9, 1]}}],
          "lights": [{"name": "cie", "point": [2, 2, 3], "axis": [0, 0, -1],
                      "lid": {"cos_power": 1, "spread_deg": 90, "candela": 1000}}]})",
      test::fixture("scenes/illuminance-test.json"));
  const WorkplaneGrid grid = make_workplane_grid(0, 0.5, {0, 0, 4, 4});
  const WorkplaneValues values = evaluate_workplane(IlluminanceSolver(scene), grid);
  double minimum = 1e300, maximum = 0, sum = 0;
  int counted = 0, inside = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double x = 0.25 + 0.5 * i, y = 0.25 + 0.5 * j;
      if (x > 3.1 && x < 3.9 && y > 3.1 && y < 3.9) {
        ++inside;
        continue;
      }
      // The post shades nothing here: it stands beyond every point it could hide from the lamp.
      const double e = cie_field(x, y);
      minimum = std::min(minimum, e);
      maximum = std::max(maximum, e);
      sum += e;
      ++counted;
    }
  const WorkplaneStatistics statistics = workplane_statistics(values);
  BOOST_TEST(inside == 4);
  BOOST_TEST(statistics.excluded == 4u);
  BOOST_TEST(statistics.points == 60u);
  BOOST_TEST(statistics.minimum == minimum, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(statistics.maximum == maximum, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(statistics.average == sum / counted, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(statistics.uniformity == minimum / (sum / counted),
             boost::test_tools::tolerance(1e-12));
}

// Isolux lines of the CIE field are circles: rho = sqrt(sqrt(9000 / L) - 9). Every traced
// point lies on its circle to within the interpolation error of a 5 cm grid, and the lines
// that fit in the region close.
BOOST_AUTO_TEST_CASE(isolux_lines_of_a_radial_field_are_circles) {
  const Scene scene = parse_scene(
      R"({"penumbra": 1, "objects": [],
          "lights": [{"name": "cie", "point": [2, 2, 3], "axis": [0, 0, -1],
                      "lid": {"cos_power": 1, "spread_deg": 90, "candela": 1000}}]})",
      test::fixture("scenes/illuminance-test.json"));
  const WorkplaneValues values =
      evaluate_workplane(IlluminanceSolver(scene), make_workplane_grid(0, 0.05, {0, 0, 4, 4}));
  const std::vector<double> levels{60, 70, 90, 100};  // radii 1.80 to 0.70 m: inside
  const std::vector<IsoluxLine> lines = isolux_lines(values, levels);
  BOOST_TEST_REQUIRE(lines.size() == levels.size());
  for (const IsoluxLine& line : lines) {
    const double radius = std::sqrt(std::sqrt(9000 / line.level) - 9);
    BOOST_TEST(line.closed);
    BOOST_TEST(line.points.size() > 20u);
    for (const PlanPoint& p : line.points)
      BOOST_TEST(std::hypot(p[0] - 2, p[1] - 2) == radius, boost::test_tools::tolerance(2e-3));
  }
  // The SVG carries one polyline per line, the legend and the levels as labels.
  std::ostringstream svg;
  io::write_isolux_svg(svg, scene, values, levels);
  const std::string text = svg.str();
  std::size_t polylines = 0;
  for (std::size_t at = text.find("<polyline"); at != std::string::npos;
       at = text.find("<polyline", at + 1))
    ++polylines;
  BOOST_TEST(polylines == lines.size());
  BOOST_TEST(text.find(">70</text>") != std::string::npos);
  BOOST_TEST(text.find("id=\"legend\"") != std::string::npos);
}

// An area source is drawn in plan as its polygon, named; its corner (1.5, 1.5) lands where a
// point lamp placed there is drawn (the same plan transform).
BOOST_AUTO_TEST_CASE(area_sources_are_drawn_as_their_polygons) {
  const Scene scene = parse_scene(
      R"({"penumbra": 1, "objects": [],
          "lights": [{"name": "troffer", "area": [[1.5,1.5,3],[1.5,2.5,3],[2.5,2.5,3],[2.5,1.5,3]],
                      "luminance": 1000},
                     {"name": "mark", "point": [1.5, 1.5, 3], "candela": 1}]})",
      "area-plan.json");
  const WorkplaneValues values =
      evaluate_workplane(IlluminanceSolver(scene), make_workplane_grid(0, 0.1, {0, 0, 4, 4}));
  std::ostringstream svg;
  io::write_isolux_svg(svg, scene, values, {50, 100});
  const std::string text = svg.str();
  const std::string tag = "<polygon points=\"";
  const std::size_t polygon = text.find(tag) + tag.size();
  BOOST_TEST_REQUIRE(polygon != std::string::npos + tag.size());
  const std::string points = text.substr(polygon, text.find('"', polygon) - polygon);
  const std::size_t circle = text.find("<circle cx=\"");
  BOOST_TEST_REQUIRE(circle != std::string::npos);
  const std::size_t cx = circle + 12, cy = text.find("cy=\"", cx) + 4;
  const std::string corner =
      text.substr(cx, text.find('"', cx) - cx) + "," + text.substr(cy, text.find('"', cy) - cy);
  BOOST_TEST(points.substr(0, corner.size()) == corner, points << " against " << corner);
  BOOST_TEST(std::count(points.begin(), points.end(), ',') == 4);
  BOOST_TEST(text.find(">troffer</text>") != std::string::npos);
  // Lights are clipped to the plot (a panel beyond the region must not cover the legend).
  BOOST_TEST(text.find("<g id=\"lights\" font-size=\"10\" clip-path=\"url(#plot)\">") !=
             std::string::npos);
}

BOOST_AUTO_TEST_CASE(levels_are_nice_numbers) {
  const std::vector<double> wide = isolux_levels(3, 49000);
  BOOST_TEST_REQUIRE(!wide.empty());
  BOOST_TEST(wide.front() == 50.0);  // the lowest 1-2-5 value above max / 1000 = 49
  BOOST_TEST(wide.back() == 20000.0);
  const std::vector<double> narrow = isolux_levels(31.1, 111.1);
  BOOST_TEST(narrow.front() == 40.0);  // steps of 10 (range 80 / 8)
  BOOST_TEST(narrow.back() == 110.0);
  BOOST_TEST(isolux_levels(5, 5).empty());
}

BOOST_AUTO_TEST_CASE(picture_levels_leave_out_the_extreme_two_percent) {
  // 1, 2, ..., 1000 lx and ten unlit pixels: the 2nd and 98th percentiles of the positive
  // values are the values of rank floor(0.02 x 999) = 19 and floor(0.98 x 999) = 979, 20 and
  // 980 lx; 980 / 20 > 20, so the 1-2-5 series strictly between them.
  std::vector<double> values(10, 0.0);
  for (int k = 1000; k >= 1; --k) values.push_back(k);
  BOOST_TEST(picture_levels(values) == (std::vector<double>{50, 100, 200, 500}),
             boost::test_tools::per_element());
  BOOST_TEST(picture_levels({0, 0}).empty());
}

BOOST_AUTO_TEST_SUITE_END()
