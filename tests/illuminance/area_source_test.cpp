#include <boost/test/unit_test.hpp>

#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/area_source.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/shadow/source_view.h"
#include "scene_support.h"

namespace {

using namespace penumbra;
using namespace penumbra::illuminance;
using penumbra::pi;
using penumbra::test::close;
using penumbra::test::scene_from;

// A panel as scene text: a rectangle corner + s u + t v, emitting on the side of u x v.
std::string panel(const Vec3d& corner, const Vec3d& u, const Vec3d& v, double luminance) {
  std::ostringstream text;
  text.precision(17);
  const auto point = [&](double s, double t) {
    text << "[" << corner[0] + s * u[0] + t * v[0] << "," << corner[1] + s * u[1] + t * v[1] << ","
         << corner[2] + s * u[2] + t * v[2] << "]";
  };
  text << R"({"name": "panel", "area": [)";
  point(0, 0);
  text << ",";
  point(1, 0);
  text << ",";
  point(1, 1);
  text << ",";
  point(0, 1);
  text << R"(], "luminance": )" << luminance << "}";
  return text.str();
}

// Objects as scene text: count hulls "c0", "c1", ... of 6 random points each, within spread
// (half as much in z) of a centre over x, y in [1.2, 2.8] and z in [low, high].
std::string random_hulls(std::mt19937& random, int count, double low, double high, double spread) {
  std::uniform_real_distribution<double> centre(1.2, 2.8), height(low, high),
      offset(-spread, spread);
  std::ostringstream objects;
  for (int k = 0; k < count; ++k) {
    const double x = centre(random), y = centre(random), z = height(random);
    objects << (k ? "," : "") << R"({"name": "c)" << k << R"(", "convex": [)";
    for (int i = 0; i < 6; ++i)
      objects << (i ? "," : "") << "[" << x + offset(random) << "," << y + offset(random) << ","
              << z + offset(random) / 2 << "]";
    objects << "]}";
  }
  return objects.str();
}

// The form factor from a differential area to a parallel rectangle a x b at distance c,
// the area's normal through one corner (Howell's catalogue, B-3; E = pi L F).
double parallel_corner(double a, double b, double c) {
  const double x = a / c, y = b / c;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
         (2 * pi);
}

// The form factor from a differential area to a rectangle in a perpendicular plane: the
// rectangle of width a (along the planes' common direction, from the area's foot) and height
// c (from the area's plane), at distance b from the area (Howell's catalogue, B-2), with X =
// c / a and Y = b / a. Checked in docs/area-sources.md against a numerical double integral.
double perpendicular_corner(double a, double b, double c) {
  const double x = c / a, y = b / a, d = std::sqrt(x * x + y * y);
  return (std::atan(1 / y) - y / d * std::atan(1 / d)) / (2 * pi);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(area_source)

// Lambert's edge sum against the catalogue's closed forms: a 1.3 x 0.7 panel 2 m above the
// point, its corner over the point, and the same panel standing on the point's plane.
BOOST_AUTO_TEST_CASE(unoccluded_equals_form_factors_of_rectangles) {
  const double luminance = 1234.5;
  for (const auto& [a, b, c] :
       {std::array<double, 3>{1.3, 0.7, 2.0}, {0.2, 5.0, 0.3}, {10.0, 10.0, 0.01}}) {
    // Parallel: corner (0, 0, c), emitting downward (counter-clockwise seen from below).
    const Scene over = scene_from("", panel({0, 0, c}, {0, b, 0}, {a, 0, 0}, luminance));
    const double e = IlluminanceSolver(over).at({0, 0, 0}, {0, 0, 1}).total;
    BOOST_TEST(close(e, pi * luminance * parallel_corner(a, b, c), 1e-9), e);
    // Perpendicular: in the plane y = b, x in [0, a], z in [0, c], emitting toward -y.
    const Scene beside = scene_from("", panel({0, b, 0}, {a, 0, 0}, {0, 0, c}, luminance));
    const double f = IlluminanceSolver(beside).at({0, 0, 0}, {0, 0, 1}).total;
    BOOST_TEST(close(f, pi * luminance * perpendicular_corner(a, b, c), 1e-9), f);
  }
}

// The back of a one-sided source gives nothing; a two-sided one gives the same from both
// sides; the luminance may be given as exitance or flux.
BOOST_AUTO_TEST_CASE(sides_and_photometric_quantities) {
  const std::string area = R"("area": [[0,0,2],[0,1,2],[1,1,2],[1,0,2]])";
  const Scene down = scene_from("", R"({"name": "p", )" + area + R"(, "luminance": 100})");
  const Scene up = scene_from("", R"({"name": "p", )" + area + R"(, "exitance": 314.159})");
  const Scene both = scene_from(
      "", R"({"name": "p", )" + area + R"(, "lumens": 628.31853071795862, "two_sided": true})");
  const double below = IlluminanceSolver(down).at({0.5, 0.5, 0}, {0, 0, 1}).total;
  BOOST_TEST(below > 0);
  BOOST_TEST(IlluminanceSolver(down).at({0.5, 0.5, 4}, {0, 0, -1}).total == 0);
  BOOST_TEST(close(IlluminanceSolver(up).at({0.5, 0.5, 0}, {0, 0, 1}).total,
                   below * 314.159 / (100 * pi), 1e-12));
  // 2 pi L A lumens from two sides of 1 m^2: L = 100.
  BOOST_TEST(close(IlluminanceSolver(both).at({0.5, 0.5, 0}, {0, 0, 1}).total, below, 1e-12));
  BOOST_TEST(close(IlluminanceSolver(both).at({0.5, 0.5, 4}, {0, 0, -1}).total, below, 1e-12));
}

// CIE 171:2006 test case 5.3 (area source): a 1 m x 1 m Lambertian panel of 1000 cd/m^2
// centred in the ceiling (z = 3) of a 4 m x 4 m x 3 m room, facing down. Points A-F on the
// wall y = 0 at x = 2, z = 2.75 ... 0.25; G-N on the floor at x = 2, y = 0.25 ... 3.75. The
// published values (Table 12) are as transcribed by github.com/jjathompson4/CyclesCIEtest,
// engine/cie171/test_cases.py (the CIE report itself is not public); they differ from the
// closed form by up to a few tenths of a percent (docs/area-sources.md lists both errors).
BOOST_AUTO_TEST_CASE(cie_171_test_5_3_area_source) {
  const Scene room = scene_from("", panel({1.5, 1.5, 3}, {0, 1, 0}, {1, 0, 0}, 1000));
  const IlluminanceSolver solver(room);
  const double table[] = {32.68, 75.09, 81.38,  69.12,  53.41, 39.90, 61.27,
                          79.18, 95.52, 105.89, 105.89, 95.52, 79.18, 61.27};
  for (int k = 0; k < 14; ++k) {
    double e, lambert;
    if (k < 6) {
      // Wall point (2, 0, z), normal +y: the panel is a perpendicular rectangle at distance
      // 3 - z, x in [1.5, 2.5] (two halves of width 0.5 from the foot), y in [1.5, 2.5]
      // (heights 2.5 less 1.5 from the point's plane).
      const double z = 2.75 - 0.5 * k, b = 3 - z;
      e = solver.at({2, 0, z}, {0, 1, 0}).total;
      lambert =
          pi * 1000 * 2 * (perpendicular_corner(0.5, b, 2.5) - perpendicular_corner(0.5, b, 1.5));
    } else {
      // Floor point (2, y, 0): four parallel rectangles with a corner over the point.
      const double y = 0.25 + 0.5 * (k - 6);
      e = solver.at({2, y, 0}, {0, 0, 1}).total;
      const auto corner = [](double a, double b) {
        return std::copysign(1.0, a) * std::copysign(1.0, b) *
               parallel_corner(std::abs(a), std::abs(b), 3);
      };
      // Signed superposition over x in [1.5, 2.5] and y' in [1.5, 2.5] around the foot.
      lambert = pi * 1000 *
                (corner(0.5, 2.5 - y) - corner(0.5, 1.5 - y) - corner(-0.5, 2.5 - y) +
                 corner(-0.5, 1.5 - y));
    }
    BOOST_TEST(close(e, lambert, 1e-9), "point " << char('A' + k) << ": " << e);
    BOOST_TEST(close(e, table[k], 3e-3),
               "point " << char('A' + k) << ": " << e << " against " << table[k]);
  }
}

// The flux on the six surfaces of a 4 m x 4 m x 3 m room (0 <= x, y <= 4, 0 <= z <= 3), each
// rectangle's by a 20-point Gauss-Legendre rule on 4 x 4 squares: the illuminance is analytic
// on each closed surface when the source is away from it, so the rule's error is far below
// 1e-9.
double room_flux(const IlluminanceSolver& solver) {
  const QuadratureRule rule = gauss_legendre(20);
  // the flux on the rectangle origin + s u + t v (s, t in [0, 1]) with unit normal n.
  const auto flux = [&](const Vec3d& o, const Vec3d& u, const Vec3d& v, const Vec3d& n) {
    double sum = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (std::size_t a = 0; a < rule.nodes.size(); ++a)
          for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
            const double s = (i + 0.5 + 0.5 * rule.nodes[a]) / 4;
            const double t = (j + 0.5 + 0.5 * rule.nodes[b]) / 4;
            const Vec3d p{o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1],
                          o[2] + s * u[2] + t * v[2]};
            sum += rule.weights[a] * rule.weights[b] / 4 * solver.at(p, n).total;
          }
    return sum / 16;  // each square is 1/16 of the unit square; the weights sum to 2 x 2
  };
  return 16 * flux({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 1}) +
         16 * flux({0, 0, 3}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}) +
         12 * flux({0, 0, 0}, {4, 0, 0}, {0, 0, 3}, {0, 1, 0}) +
         12 * flux({0, 4, 0}, {4, 0, 0}, {0, 0, 3}, {0, -1, 0}) +
         12 * flux({0, 0, 0}, {0, 4, 0}, {0, 0, 3}, {1, 0, 0}) +
         12 * flux({4, 0, 0}, {0, 4, 0}, {0, 0, 3}, {-1, 0, 0});
}

// Flux conservation for the area source: everything the panel of 5.3 emits, pi L A =
// 1000 pi lm, lands on the floor and the four walls of the room (the ceiling, in the panel's
// plane, gets nothing).
BOOST_AUTO_TEST_CASE(flux_conservation_in_the_room_of_5_3) {
  const Scene room = scene_from("", panel({1.5, 1.5, 3}, {0, 1, 0}, {1, 0, 0}, 1000));
  BOOST_TEST(close(room_flux(IlluminanceSolver(room)), 1000 * pi, 1e-9));
}

// CIE 171:2006 test case 5.4 (luminous flux conservation): an isotropic point source of
// 10,000 lm in the 4 m x 4 m x 3 m room with black surfaces; the flux on its surfaces must be
// the flux emitted. The case as transcribed in github.com/jjathompson4/CyclesCIEtest
// (engine/cie171/test_cases.py, TEST_5_4), which gives no position: the room's centre here.
BOOST_AUTO_TEST_CASE(cie_171_test_5_4_flux_conservation) {
  std::ostringstream lamp;
  lamp.precision(17);
  lamp << R"({"name": "iso", "point": [2, 2, 1.5], "candela": )" << 10000 / (4 * pi) << "}";
  BOOST_TEST(close(room_flux(IlluminanceSolver(scene_from("", lamp.str()))), 10000, 1e-9));
}

// Half a unit of the last digit a table prints: a value that rounds to the printed one.
bool rounds_to(double value, double printed, double unit) {
  return std::abs(value - printed) <= 0.5 * unit + 1e-12;
}

// CIE 171:2006 test case 5.6, scenario 2 (light reflection over diffuse surfaces): a 4 m x
// 4 m floor S2 of uniform exitance (a Lambertian reflector, rho E_hz) lights a wall y = 0
// (points B-F at x = 2, z = 0.75 ... 2.75, normal +y) and a ceiling z = 3 (points G-N at
// x = 2, y = 0.25 ... 3.75, normal -z); the table gives E / (E_hz rho) in percent, the
// configuration factor: an area source of exitance 100 lm/m2 gives it in lux. Table 17 as
// transcribed in github.com/jjathompson4/CyclesCIEtest (engine/cie171/test_cases.py,
// TEST_5_6_SCENARIO2; point A lies below that scenario's wall). Checked against the form
// factors of rectangles written here (Howell B-2 and B-3) to 1e-9 and against the table to its
// printed digits.
BOOST_AUTO_TEST_CASE(cie_171_test_5_6_diffuse_reflection) {
  const Scene room = scene_from(
      "", R"({"name": "s2", "area": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]], "exitance": 100})");
  const IlluminanceSolver solver(room);
  const double wall[] = {35.901, 27.992, 21.639, 16.716, 12.967};
  for (int k = 0; k < 5; ++k) {
    // (2, 0, z), normal +y: the floor is a perpendicular rectangle below at distance z, two
    // halves of width 2 beside the foot, reaching 4 m along the normal.
    const double z = 0.75 + 0.5 * k;
    const double e = solver.at({2, 0, z}, {0, 1, 0}).total;
    BOOST_TEST(close(e, 100 * 2 * perpendicular_corner(2, z, 4), 1e-9));
    BOOST_TEST(rounds_to(e, wall[k], 1e-3), "point " << char('B' + k) << ": " << e);
  }
  const double ceiling[] = {26.80, 30.94, 33.98, 35.57, 35.57, 33.98, 30.94, 26.80};
  for (int k = 0; k < 8; ++k) {
    // (2, y, 3), normal -z: four parallel rectangles 3 m away with a corner over the point.
    const double y = 0.25 + 0.5 * k;
    const double e = solver.at({2, y, 3}, {0, 0, -1}).total;
    const auto corner = [](double a, double b) {
      return std::copysign(1.0, a) * std::copysign(1.0, b) *
             parallel_corner(std::abs(a), std::abs(b), 3);
    };
    const double lambert =
        100 * (corner(2, 4 - y) - corner(2, -y) - corner(-2, 4 - y) + corner(-2, -y));
    BOOST_TEST(close(e, lambert, 1e-9));
    BOOST_TEST(rounds_to(e, ceiling[k], 1e-2), "point " << char('G' + k) << ": " << e);
  }
}

// CIE 171:2006 test case 5.7 (diffuse reflections with internal obstructions): a wall S2
// (y = 4, 0 <= x <= 4, 0 <= z <= 3) of uniform exitance lights, past a black box
// 0 <= x <= 4, 2.5 <= y <= 2.7, 0 <= z <= 1, a wall y = 0 (A-F at x = 2, z = 2.75 ... 0.25,
// normal +y) and the floor (G-K at x = 2, y = 0.25 ... 2.25, normal +z); E / (E_v rho) in
// percent. The report's Table 19 is wrong (the published errata); the values here are the
// corrected ones of NVIDIA's Iray validation report (its Table 14), as transcribed in
// github.com/jjathompson4/CyclesCIEtest (TEST_5_7). J and K are exactly 0: from (2, y, 0)
// with y >= 1.75 a segment to (x', 4, z'), z' < 3, crosses y = 2.5 at height
// z' (2.5 - y) / (4 - y) <= z' / 3 < 1 and 0 <= x <= 4, through the box's face.
BOOST_AUTO_TEST_CASE(cie_171_test_5_7_internal_obstructions) {
  const Scene room =
      scene_from(R"({"name": "box", "box": {"min": [0, 2.5, 0], "max": [4, 2.7, 1]}})",
                 R"({"name": "s2", "area": [[0,4,0],[4,4,0],[4,4,3],[0,4,3]], "exitance": 100})");
  const IlluminanceSolver solver(room);
  const double wall[] = {16.07, 16.33, 15.40, 13.32, 10.32, 7.08};
  for (int k = 0; k < 6; ++k) {
    const double e = solver.at({2, 0, 2.75 - 0.5 * k}, {0, 1, 0}).total;
    BOOST_TEST(rounds_to(e, wall[k], 1e-2), "point " << char('A' + k) << ": " << e);
  }
  const double floor[] = {3.38, 3.63, 3.01, 0, 0};
  for (int k = 0; k < 5; ++k) {
    const double e = solver.at({2, 0.25 + 0.5 * k, 0}, {0, 0, 1}).total;
    BOOST_TEST(rounds_to(e, floor[k], 1e-2), "point " << char('G' + k) << ": " << e);
    if (k >= 3) BOOST_TEST(e == 0);
  }
}

// Occluded points against a quadrature over the source with exact visibility per row: the
// panel's rows y = const are linear sources whose exactly visible intervals from the point
// the solver gives (visible_parts, the linear path: exact interval arithmetic on the tube,
// not the polygon Booleans of the area path). Along each visible interval the integrand
// L cos(alpha) cos(theta) / r^2 is smooth (10-point Gauss-Legendre, error ~1e-15); across
// rows the row integral g(y) is continuous with kinks where a row passes a vertex of a hidden
// polygon, so the composite 4-point rule on M panels errs by ~h^2 |jump of g'| per kink
// (h = 1/M). Bound used: 2e-6 of the unoccluded value at M = 256, with the check that
// M = 128 differs from it by less than that (the error falls as M^-2). Three random solids
// (fixed seed) under the panel of 5.3; 12 random points on the floor.
BOOST_AUTO_TEST_CASE(occluded_points_against_row_quadrature) {
  std::mt19937 random(20261203);
  // Hulls of 6 random points: no edge parallel to the rows, whose shadow edge would make
  // g(y) jump (a jump costs the rule O(h), not O(h^2)).
  std::ostringstream boxes;
  boxes << random_hulls(random, 3, 1.0, 2.3, 0.45);
  const double luminance = 1000;
  const Scene scene =
      scene_from(boxes.str(), panel({1.5, 1.5, 3}, {0, 1, 0}, {1, 0, 0}, luminance));
  const IlluminanceSolver solver(scene);
  const Scene open = scene_from("", panel({1.5, 1.5, 3}, {0, 1, 0}, {1, 0, 0}, luminance));
  const IlluminanceSolver unoccluded(open);

  // one tube per row y of the composite rule with M panels, in one scene.
  const QuadratureRule rule = gauss_legendre(4), inner = gauss_legendre(10);
  const auto rows_of = [&](int panels) {
    std::vector<double> ys, weights;
    std::ostringstream tubes;
    for (int i = 0; i < panels; ++i)
      for (std::size_t a = 0; a < rule.nodes.size(); ++a) {
        const double y = 1.5 + (i + 0.5 + 0.5 * rule.nodes[a]) / panels;
        tubes << (ys.empty() ? "" : ",") << R"({"name": "row)" << ys.size()
              << R"(", "linear": [[1.5,)" << y << R"(,3],[2.5,)" << y
              << R"(,3]], "candela_per_metre": 1})";
        ys.push_back(y);
        weights.push_back(rule.weights[a] / (2.0 * panels));
      }
    return std::make_tuple(ys, weights, tubes.str());
  };
  const auto reference = [&](const Vec3d& p, int panels) {
    const auto [ys, weights, tubes] = rows_of(panels);
    const IlluminanceSolver rows(scene_from(boxes.str(), tubes));
    double sum = 0;
    for (std::size_t r = 0; r < ys.size(); ++r)
      for (const ExactInterval& part : rows.visible_parts(r, p, {0, 0, 1})) {
        const double u0 = CGAL::to_double(part.low), u1 = CGAL::to_double(part.high);
        for (std::size_t a = 0; a < inner.nodes.size(); ++a) {
          const double x = 1.5 + u0 + (u1 - u0) * 0.5 * (1 + inner.nodes[a]);
          const Vec3d d{x - p[0], ys[r] - p[1], 3 - p[2]};
          const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
          // cos(alpha) = d_z / r at the floor, cos(theta) = d_z / r at the panel.
          sum +=
              weights[r] * inner.weights[a] * 0.5 * (u1 - u0) * luminance * d[2] * d[2] / (r2 * r2);
        }
      }
    return sum;
  };
  std::uniform_real_distribution<double> floor(1.0, 3.0);
  int shaded = 0;
  for (int k = 0; k < 12; ++k) {
    const Vec3d p{floor(random), floor(random), 0};
    const double e = solver.at(p, {0, 0, 1}).total;
    const double bound = 2e-6 * unoccluded.at(p, {0, 0, 1}).total;
    const double fine = reference(p, 256), coarse = reference(p, 128);
    BOOST_TEST_MESSAGE(std::setprecision(12)
                       << k << " " << e << " " << fine << " " << coarse << " " << bound);
    BOOST_TEST(std::abs(fine - coarse) < bound, "the reference has not converged at " << k);
    BOOST_TEST(std::abs(e - fine) < bound, "point " << k << ": " << e << " against " << fine);
    shaded += e < unoccluded.at(p, {0, 0, 1}).total * (1 - 1e-3);
  }
  BOOST_TEST(shaded >= 4);  // the points test occlusion, not only the open panel
}

// Two boxes that hide the panel together, neither alone: from below (1, 1, 0) box A hides the
// panel's x <= 1 + 0.05 * 3 / 1.4 = 1.107 and box B its x >= 1 - 0.05 * 3 / 1.4 = 0.893, both
// all of its y (their bottoms at 1.4 m, under the panel at 3 m, scale by 3 / 1.4). The
// inclusion and exclusion sum P - A - B + AB is 0; rounding must not make the lux negative.
BOOST_AUTO_TEST_CASE(a_source_hidden_by_two_occluders_together_gives_zero_not_less) {
  const Scene scene = scene_from(
      R"({"name": "a", "box": {"min": [0.2, 0.2, 1.4], "max": [1.05, 1.8, 1.6]}},
         {"name": "b", "box": {"min": [0.95, 0.2, 1.4], "max": [1.8, 1.8, 1.6]}})",
      panel({0, 0, 3}, {0, 2, 0}, {2, 0, 0}, 1000));
  const IlluminanceSolver solver(scene);
  std::mt19937 random(55);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (int k = 0; k < 200; ++k) {
    const double e = solver.at({1 + jitter(random), 1 + jitter(random), 0}, {0, 0, 1}).total;
    BOOST_TEST(e >= 0.0, "point " << k << ": " << e);
    BOOST_TEST(e <= 1e-9, "point " << k << ": " << e);
  }
}

// The solver decides the visible part in intervals when they are certain (area_visibility.cpp)
// and exactly otherwise: its value must be Lambert's sum over the exact visible part
// (visible_source, rationals throughout) to rounding, at random points with random receiving
// normals, among random hulls, boxes whose faces line up with the panel's edges (planes
// through the point and an edge of both) and a box touching the panel's plane (the interval
// path leaves that one to the exact path).
BOOST_AUTO_TEST_CASE(interval_path_equals_the_exact_visible_part) {
  std::mt19937 random(4242);
  std::ostringstream objects;
  objects << random_hulls(random, 4, 1.2, 2.4, 0.4);
  objects << R"(, {"name": "aligned", "box": {"min": [1.5, 1.5, 2], "max": [2, 2, 2.2]}})"
          << R"(, {"name": "touching", "box": {"min": [2.4, 1.2, 2.7], "max": [2.7, 1.6, 3]}})";
  const double luminance = 1000;
  const Scene scene =
      scene_from(objects.str(), panel({1.5, 1.5, 3}, {0, 1, 0}, {1, 0, 0}, luminance));
  const IlluminanceSolver solver(scene);
  const auto& source = std::get<AreaLight>(scene.lights[0].source);
  const Face& face = source.polygon->faces()[source.front];
  std::vector<const ConvexPolyhedron*> occluders;
  for (const Object& object : scene.objects) occluders.push_back(&object.solid);
  std::uniform_real_distribution<double> floor(0.5, 3.5), tilt(-0.6, 0.6);
  int partly = 0;
  for (int k = 0; k < 400; ++k) {
    // Every fourth point on the grid of the aligned box's edges (x, y in {1.5, 2}).
    const Vec3d p = k % 4 ? Vec3d{floor(random), floor(random), tilt(random) + 0.6}
                          : Vec3d{1.5 + 0.5 * (k / 4 % 2), 1.5 + 0.5 * (k / 8 % 2), 0.2};
    Vec3d n{tilt(random), tilt(random), 1};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n) c /= length;
    std::vector<std::vector<Vec3d>> rings;
    const Point3 x = to_exact(p);
    for (const Ring2& ring : visible_source(face, x, Plane3(x, to_exact_vector(n)), occluders)) {
      rings.emplace_back();
      for (const Point2& q : ring) rings.back().push_back(to_double(face.frame.to_world(q)));
    }
    const double exact = luminance * projected_solid_angle(p, n, rings);
    const double open =
        luminance *
        projected_solid_angle(p, n, {{{1.5, 1.5, 3}, {1.5, 2.5, 3}, {2.5, 2.5, 3}, {2.5, 1.5, 3}}});
    const double e = solver.light_at(0, p, n);
    BOOST_TEST(std::abs(e - exact) <= 1e-9 * std::abs(open) + 1e-12,
               "point " << k << ": " << e << " against " << exact);
    partly += exact > 1e-6 * open && exact < (1 - 1e-6) * open;
  }
  BOOST_TEST(partly > 100);
}

BOOST_AUTO_TEST_SUITE_END()
