// SVG sheets draw the arcs of ellipses of curved regions (shadows --joint-umbrae, issue #17)
// as SVG elliptical arcs. A ring along an ellipse (centre (1, 2), semi-axes 3 and 1, turned
// 30 degrees, from 20 to 250 degrees every 0.1 degree: chords within 1e-3 px of it at the
// scales drawn) and closed by a chord is drawn by emit() with the arc
// and again as lines only; the arc command is read back with the SVG specification's
// conversion from end points to centre (SVG 1.1 appendix F.6.5, written out here), and its
// points must lie on the lines within 0.01 px, the flags choosing the right one of the four
// candidate arcs.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "svg_drawing.h"

using namespace penumbra::io;

namespace {

constexpr double pi = 3.14159265358979323846;

Flat on_ellipse(double degrees) {
  const double t = degrees * pi / 180, turn = pi / 6;
  const double x = 3 * std::cos(t), y = std::sin(t);
  return {1 + x * std::cos(turn) - y * std::sin(turn), 2 + x * std::sin(turn) + y * std::cos(turn)};
}

// (p - c)^T Q (p - c) = 1 for the ellipse: Q = R diag(1/9, 1) R^T.
EllipseArc the_arc(std::size_t first, std::size_t last) {
  const double c = std::cos(pi / 6), s = std::sin(pi / 6), a = 1.0 / 9, b = 1;
  return {first, last, {1, 2}, {a * c * c + b * s * s, (a - b) * c * s, a * s * s + b * c * c}};
}

// The path commands of each <path> element, as letters followed by numbers.
struct Command {
  char letter;
  std::vector<double> values;
};

std::vector<std::vector<Command>> paths_of(const std::string& svg) {
  std::vector<std::vector<Command>> paths;
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos;
       at = svg.find(" d=\"", at + 1)) {
    const std::size_t end = svg.find('"', at + 4);
    std::istringstream in(svg.substr(at + 4, end - at - 4));
    std::vector<Command> path;
    char c;
    while (in >> c) {
      if (std::isalpha(static_cast<unsigned char>(c))) {
        path.push_back({c, {}});
      } else {
        in.putback(c);
        double x;
        in >> x;
        path.back().values.push_back(x);
      }
    }
    paths.push_back(path);
  }
  return paths;
}

double distance_to_polyline(const Flat& p, const std::vector<Flat>& line) {
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Flat& a = line[k];
    const Flat& b = line[k + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t =
        std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
  }
  return best;
}

// Points of the SVG arc from (x1, y1) by the command's values rx ry phi large sweep x2 y2.
std::vector<Flat> arc_points(const Flat& from, const std::vector<double>& v) {
  double rx = v[0], ry = v[1];
  const double phi = v[2] * pi / 180, x2 = v[5], y2 = v[6];
  const bool large = v[3] != 0, sweep = v[4] != 0;
  const double cp = std::cos(phi), sp = std::sin(phi);
  const double dx = (from[0] - x2) / 2, dy = (from[1] - y2) / 2;
  const double x1p = cp * dx + sp * dy, y1p = -sp * dx + cp * dy;
  const double lambda = x1p * x1p / (rx * rx) + y1p * y1p / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);  // F.6.6: radii too small
  const double num = rx * rx * ry * ry - rx * rx * y1p * y1p - ry * ry * x1p * x1p;
  const double den = rx * rx * y1p * y1p + ry * ry * x1p * x1p;
  const double k = (large != sweep ? 1 : -1) * std::sqrt(std::max(0.0, num / den));
  const double cxp = k * rx * y1p / ry, cyp = -k * ry * x1p / rx;
  const double cx = cp * cxp - sp * cyp + (from[0] + x2) / 2;
  const double cy = sp * cxp + cp * cyp + (from[1] + y2) / 2;
  const auto angle = [](double ux, double uy, double vx, double vy) {
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  };
  const double theta = angle(1, 0, (x1p - cxp) / rx, (y1p - cyp) / ry);
  double delta = angle((x1p - cxp) / rx, (y1p - cyp) / ry, (-x1p - cxp) / rx, (-y1p - cyp) / ry);
  if (!sweep && delta > 0) delta -= 2 * pi;
  if (sweep && delta < 0) delta += 2 * pi;
  std::vector<Flat> points;
  for (int j = 0; j <= 40; ++j) {
    const double t = theta + delta * j / 40;
    points.push_back({cx + rx * cp * std::cos(t) - ry * sp * std::sin(t),
                      cy + rx * sp * std::cos(t) + ry * cp * std::sin(t)});
  }
  return points;
}

// draws the ring with the arc and as lines; returns the two paths.
std::vector<std::vector<Command>> drawn(const std::vector<Flat>& ring, const EllipseArc& arc) {
  FaceDrawing drawing{0, {}};
  drawing.shapes.push_back({{ring}, "fill=\"none\"", {{arc}}});
  drawing.shapes.push_back({{ring}, "fill=\"none\""});
  std::ostringstream out;
  emit(out, {drawing}, 10, 20, 500, 400, true);
  return paths_of(out.str());
}

// checks the one arc command of path against the lines of plain; returns the arcs found.
int check_arc(const std::vector<Command>& path, const std::vector<Command>& plain) {
  std::vector<Flat> lines;
  for (const Command& c : plain)
    if (c.letter == 'M' || c.letter == 'L') lines.push_back({c.values[0], c.values[1]});
  lines.push_back(lines.front());  // Z
  int arcs = 0;
  Flat at{0, 0};
  for (const Command& c : path) {
    if (c.letter == 'A') {
      ++arcs;
      for (const Flat& p : arc_points(at, c.values))
        BOOST_TEST(distance_to_polyline(p, lines) <= 0.01, "arc point " << p[0] << " " << p[1]);
      at = {c.values[5], c.values[6]};
    } else if (c.letter != 'Z') {
      at = {c.values[0], c.values[1]};
    }
  }
  return arcs;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(svg_arcs)

BOOST_AUTO_TEST_CASE(an_arc_of_an_ellipse_is_drawn_as_one_svg_arc_on_the_ring) {
  std::vector<Flat> ring;
  for (int d = 200; d <= 2500; ++d) ring.push_back(on_ellipse(d / 10.0));  // then the chord
  const auto paths = drawn(ring, the_arc(0, ring.size() - 1));
  BOOST_TEST_REQUIRE(paths.size() == 2u);
  BOOST_TEST(paths[0].size() == 3u);  // M, A, Z: the chord is the closing Z
  BOOST_TEST(check_arc(paths[0], paths[1]) == 1);
  BOOST_TEST(paths[1].size() == ring.size() + 1);  // M, L..., Z
}

BOOST_AUTO_TEST_CASE(an_arc_that_ends_at_the_rings_first_point_and_a_short_one) {
  // The arc from 20 to 250 degrees ends at the ring's first point (last = size).
  std::vector<Flat> ring{on_ellipse(250)};
  for (int d = 200; d < 2500; ++d) ring.push_back(on_ellipse(d / 10.0));
  auto paths = drawn(ring, the_arc(1, ring.size()));
  BOOST_TEST(check_arc(paths[0], paths[1]) == 1);
  BOOST_TEST(paths[0].size() == 4u);  // M, L (the chord), A, Z
  // An arc under 180 degrees: the small-arc flag.
  ring.clear();
  for (int d = 1000; d <= 1600; ++d) ring.push_back(on_ellipse(d / 10.0));
  paths = drawn(ring, the_arc(0, ring.size() - 1));
  BOOST_TEST(check_arc(paths[0], paths[1]) == 1);
}

BOOST_AUTO_TEST_CASE(points_off_the_ellipse_are_drawn_as_lines) {
  // The ring's points 0.1 drawing units (over 1 px at this scale) off the ellipse: no arc.
  std::vector<Flat> ring;
  for (int d = 200; d <= 2500; ++d) {
    Flat p = on_ellipse(d / 10.0);
    if (d == 1000) p[1] += 0.1;
    ring.push_back(p);
  }
  const auto paths = drawn(ring, the_arc(0, ring.size() - 1));
  BOOST_TEST(check_arc(paths[0], paths[1]) == 0);
  BOOST_TEST(paths[0].size() == paths[1].size());
}

BOOST_AUTO_TEST_SUITE_END()
