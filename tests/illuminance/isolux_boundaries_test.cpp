// Exact isolux lines (issue #18; docs/illuminance.md, "Exact isolux lines"): the work-plane
// isolux SVG draws the exact shadow edges, every vertex of the sun's exact shadow polygon lies
// on a drawn edge, and no isolux line crosses one. What a user sees: the SVG is read back.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {

using Point = std::array<double, 2>;
using Segment = std::array<Point, 2>;

// returns the text of the group <g id="name" ...> ... </g> (groups are not nested here).
std::string group(const std::string& svg, const std::string& name) {
  const std::size_t start = svg.find("<g id=\"" + name + "\"");
  BOOST_TEST_REQUIRE(start != std::string::npos, name);
  return svg.substr(start, svg.find("</g>", start) - start);
}

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// the convex hull of points, counter-clockwise (Andrew's monotone chain).
std::vector<Point> hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  std::vector<Point> out(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(out[k - 2], out[k - 1], points[i]) <= 0) --k;
    out[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(out[k - 2], out[k - 1], points[i]) <= 0) --k;
    out[k++] = points[i];
  }
  out.resize(k - 1);
  return out;
}

double distance_to(const Segment& s, const Point& p) {
  const double dx = s[1][0] - s[0][0], dy = s[1][1] - s[0][1];
  const double t =
      std::clamp(((p[0] - s[0][0]) * dx + (p[1] - s[0][1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(s[0][0] + t * dx - p[0], s[0][1] + t * dy - p[1]);
}

// whether a and b cross properly: each strictly on both sides of the other, by more than
// tolerance (px) of distance, so that the SVG's six-digit rounding cannot make a crossing.
bool crosses(const Segment& a, const Segment& b, double tolerance) {
  const auto side = [&](const Segment& s, const Point& p) {
    return cross(s[0], s[1], p) / std::hypot(s[1][0] - s[0][0], s[1][1] - s[0][1]);
  };
  return ((side(a, b[0]) > tolerance && side(a, b[1]) < -tolerance) ||
          (side(a, b[0]) < -tolerance && side(a, b[1]) > tolerance)) &&
         ((side(b, a[0]) > tolerance && side(b, a[1]) < -tolerance) ||
          (side(b, a[0]) < -tolerance && side(b, a[1]) > tolerance));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(isolux_boundaries)

BOOST_AUTO_TEST_CASE(sun_shadow_vertices_lie_on_drawn_edges_and_no_line_crosses_one) {
  const auto dir = scratch_dir("isolux-boundaries");
  const auto result = run_penumbra(
      "illuminance '" + fixture("scenes/isolux-sun-shadow.json").string() +
      "' --workplane 0.75 --spacing 0.1 --region 0,0,4,4 --levels 150,200,250,300,1000,20000,"
      "47100,47200,47300 -o '" +
      (dir / "grid.csv").string() + "' --svg '" + (dir / "iso.svg").string() + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const std::string svg = read_text(dir / "iso.svg");

  // the plot's frame gives the plan-to-SVG transform: x0 = y0 = 0, x1 = y1 = 4
  std::smatch frame;
  BOOST_TEST_REQUIRE(std::regex_search(
      svg, frame,
      std::regex(R"re(<rect x="([-0-9.e+]+)" y="([-0-9.e+]+)" width="([-0-9.e+]+)" )re"
                 R"re(height="([-0-9.e+]+)" fill="none" stroke="black"/>\n</svg>)re")));
  const double left = std::stod(frame[1]), top = std::stod(frame[2]);
  const double scale = std::stod(frame[3]) / 4;
  BOOST_TEST(std::stod(frame[4]) / 4 == scale, boost::test_tools::tolerance(1e-6));
  const auto to_svg = [&](const Point& p) {
    return Point{left + p[0] * scale, top + (4 - p[1]) * scale};
  };

  std::vector<Segment> edges;
  const std::regex line_re(
      R"re(<line x1="([-0-9.e+]+)" y1="([-0-9.e+]+)" x2="([-0-9.e+]+)" y2="([-0-9.e+]+)")re");
  const std::string boundaries = group(svg, "shadow-boundaries");
  for (std::sregex_iterator it(boundaries.begin(), boundaries.end(), line_re), end; it != end; ++it)
    edges.push_back({Point{std::stod((*it)[1]), std::stod((*it)[2])},
                     Point{std::stod((*it)[3]), std::stod((*it)[4])}});
  BOOST_TEST_REQUIRE(!edges.empty());

  // The sun's exact shadow of the canopy [1.2, 2.2] x [1.4, 2.0] x [1.6, 1.8] on z = 0.75
  // along (0.3, 0.2, -1): each corner moves by (z - 0.75) (0.3, 0.2); the shadow is the
  // convex hull of the eight.
  std::vector<Point> corners;
  for (double x : {1.2, 2.2})
    for (double y : {1.4, 2.0})
      for (double z : {1.6, 1.8}) corners.push_back({x + (z - 0.75) * 0.3, y + (z - 0.75) * 0.2});
  const std::vector<Point> shadow = hull(corners);
  BOOST_TEST(shadow.size() == 6u);  // a box seen obliquely: a hexagon
  for (const Point& vertex : shadow) {
    double nearest = INFINITY;
    for (const Segment& edge : edges)
      nearest = std::min(nearest, distance_to(edge, to_svg(vertex)));
    BOOST_TEST(nearest < 2e-3, "shadow vertex " << vertex[0] << ", " << vertex[1] << ": " << nearest
                                                << " px from every drawn edge");
  }

  // Isolux lines: none crosses a drawn edge; the lines that meet the sun shadow (150 and 200
  // lx inside it) end within a refined sub-square's diagonal (1.25 cm x sqrt 2 < 1.8 cm) of
  // it, not a grid cell short
  const std::string isolux = group(svg, "isolux");
  const std::regex points_re(R"re(points="([^"]*)")re");
  std::size_t segments = 0, close = 0;
  for (std::sregex_iterator it(isolux.begin(), isolux.end(), points_re), end; it != end; ++it) {
    std::vector<Point> line;
    std::istringstream text((*it)[1].str());
    std::string pair;
    while (text >> pair) {
      const std::size_t comma = pair.find(',');
      line.push_back({std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))});
    }
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      const Segment piece{line[k], line[k + 1]};
      ++segments;
      for (const Segment& edge : edges) {
        BOOST_TEST(!crosses(piece, edge, 2e-3),
                   "isolux segment " << piece[0][0] << ',' << piece[0][1] << " crosses");
        if (distance_to(edge, line[k]) < 0.018 * scale) ++close;
      }
    }
  }
  BOOST_TEST(segments > 100u);
  BOOST_TEST(close >= 4u);
}

BOOST_AUTO_TEST_SUITE_END()
