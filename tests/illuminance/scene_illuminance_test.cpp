#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/linear_volumes.h"
#include "penumbra/shadow/shadow_map.h"
#include "reference_quadrature.h"
#include "scene_support.h"
#include "support/fixtures.h"

namespace {

using namespace penumbra;
using namespace penumbra::illuminance;
using penumbra::pi;
using penumbra::test::close;
using penumbra::test::flux_on_rectangle;
using penumbra::test::oracle_meets_interior;
using penumbra::test::oracle_segment_blocked;
using penumbra::test::reference_linear;
using penumbra::test::scene_from;

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_illuminance)

// CIE 171:2006 test case 5.2 through a scene: I(theta) = 1000 cos(theta) cd (theta from the
// downward axis), 3 m above the centre of a 4 m x 4 m floor. At horizontal distance rho,
// r^2 = 9 + rho^2 and cos(theta) = cos(alpha) = 3 / r, so E = 1000 * 9 / (9 + rho^2)^2.
// The distribution is given twice: Dobashi's cos_power with k = 1, and a table every 5
// degrees with eq. (1)'s cosine interpolation, which is linear in cos(gamma) and so
// reproduces 1000 cos(gamma) exactly between the nodes.
BOOST_AUTO_TEST_CASE(cie_171_test_5_2_through_the_scene) {
  std::string table_deg, candela;
  for (int g = 0; g <= 180; g += 5) {
    table_deg += (g ? "," : "") + std::to_string(g);
    candela += (g ? "," : "") + std::to_string(g <= 90 ? 1000 * std::cos(g * pi / 180) : 0.0);
  }
  const Scene scene = scene_from(
      R"({"name": "floor", "box": {"min": [0, 0, -0.1], "max": [4, 4, 0]}})",
      R"({"name": "formula", "point": [2, 2, 3], "axis": [0, 0, -1],
          "lid": {"cos_power": 1, "spread_deg": 90, "candela": 1000}},
         {"name": "table", "point": [2, 2, 3], "axis": [0, 0, -1],
          "lid": {"table_deg": [)" +
          table_deg + R"(], "candela": [)" + candela + R"(], "interpolation": "cosine"}})");
  const IlluminanceSolver solver(scene);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const Vec3d p{0.5 * i, 0.5 * j, 0};
      const double rho2 = (p[0] - 2) * (p[0] - 2) + (p[1] - 2) * (p[1] - 2);
      const double expected = 9000 / ((9 + rho2) * (9 + rho2));
      const PointIlluminance e = solver.at(p, {0, 0, 1});
      BOOST_TEST(close(e.per_light[0], expected, 1e-12));
      BOOST_TEST(close(e.per_light[1], expected, 1e-9));
    }
  // The average over the square: 1000 pi F / A, with F the point-to-rectangle form factor
  // of four 2 m x 2 m quarters at H = 3 (A = B = 2/3):
  //   F_quarter = (1/2pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))].
  const double ratio = 2.0 / 3, root = std::sqrt(1 + ratio * ratio);
  const double quarter = (2 * ratio / root * std::atan(ratio / root)) / (2 * pi);
  const double average = 1000 * pi * 4 * quarter / 16;
  const double flux = flux_on_rectangle(solver, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 1}, 40, 40);
  BOOST_TEST(close(flux / 16 / 2, average, 1e-6));  // two identical lights
}

// A table between its angles: linear interpolation in gamma. The lamp at (0, 0, 2) aims
// along (1, 0, -1)/sqrt(2); the point (0, 0, 0) is then at gamma = 45 degrees, between the
// 40 and 50 degree entries (I = (700 + 500) / 2 = 600 cd), at r = 2, cos(alpha) = 1:
// E = 600 / 4 = 150 lx. The point (2, 0, 0) lies on the axis (gamma = 0, 1000 cd) at
// r^2 = 8, cos(alpha) = 2/sqrt(8).
BOOST_AUTO_TEST_CASE(tabulated_distribution_between_table_angles) {
  const Scene scene = scene_from("", R"({"name": "lamp", "point": [0, 0, 2], "axis": [1, 0, -1],
              "lid": {"table_deg": [0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 180],
                      "candela":   [1000, 980, 900, 800, 700, 500, 300, 150, 50, 0, 0]}})");
  const IlluminanceSolver solver(scene);
  BOOST_TEST(close(solver.light_at(0, {0, 0, 0}, {0, 0, 1}), 150.0, 1e-12));
  BOOST_TEST(
      close(solver.light_at(0, {2, 0, 0}, {0, 0, 1}), 1000 * (2 / std::sqrt(8.0)) / 8, 1e-12));
  // A point 17.5 degrees from the nadir toward -x is 45 + 17.5 = 62.5 degrees from the
  // axis: between the 60 and 70 degree entries, I = 300 + 0.25 (150 - 300) = 262.5 cd.
  const double tilt = -17.5 * pi / 180;
  const double x = 2 * std::tan(tilt);
  const double r2 = x * x + 4, cos_alpha = 2 / std::sqrt(r2);
  const double intensity = 300 + (62.5 - 60) / 10 * (150 - 300);  // 262.5 cd
  BOOST_TEST(close(solver.light_at(0, {x, 0, 0}, {0, 0, 1}), intensity * cos_alpha / r2, 1e-12));
}

// A tube from (1, 0, -1) to (1, 0, 2) pierces the floor plane z = 0 and the floor box:
// only the part above lights P = (0, 0, 0). For the vertical element at height z, at
// horizontal distance d = 1: sin(theta) = d / r, cos(alpha) = z / r, so
//   E = I d int_0^h z / (d^2 + z^2)^2 dz = (I / 2d) h^2 / (d^2 + h^2) = I * 4 / 10 (h = 2).
BOOST_AUTO_TEST_CASE(tube_crossing_the_receiving_plane) {
  const std::string tube =
      R"({"name": "tube", "linear": [[1, 0, -1], [1, 0, 2]], "candela_per_metre": 150})";
  const Scene bare = scene_from("", tube);
  const Scene with_floor =
      scene_from(R"({"name": "floor", "box": {"min": [-3, -3, -0.5], "max": [3, 3, 0]}})", tube);
  BOOST_TEST(close(illuminance_at(bare, {0, 0, 0}, {0, 0, 1}).total, 150 * 0.4, 1e-12));
  BOOST_TEST(close(illuminance_at(with_floor, {0, 0, 0}, {0, 0, 1}).total, 150 * 0.4, 1e-12));
  // The visible part is exactly u in [1/3, 1].
  const auto parts = IlluminanceSolver(with_floor).visible_parts(0, {0, 0, 0}, {0, 0, 1});
  BOOST_TEST_REQUIRE(parts.size() == 1u);
  BOOST_TEST((parts[0].low == Exact(1) / 3 && parts[0].high == 1));
  // On the floor's underside (normal -z) only the part below z = -0.5 counts (h = 0.5), and
  // the floor, above that point, hides none of it.
  for (const Scene* scene : {&bare, &with_floor})
    BOOST_TEST(close(illuminance_at(*scene, {0, 0, -0.5}, {0, 0, -1}).total,
                     150 / 2.0 * 0.25 / 1.25, 1e-12));
}

// Points in the penumbra of a tube behind two occluders (a box and a tilted hull) against
// the midpoint rule with exact per-sample visibility, to 0.5%.
BOOST_AUTO_TEST_CASE(penumbra_points_match_quadrature_with_exact_visibility) {
  const Scene scene = scene_from(
      R"({"name": "slab", "box": {"min": [0.8, -0.3, 1.0], "max": [1.25, 0.4, 1.15]}},
         {"name": "wedge", "convex": [[1.7, -0.2, 0.6], [2.1, -0.1, 0.7], [1.9, 0.3, 0.65],
                                      [1.8, 0.0, 0.95], [2.0, 0.1, 0.5]]})",
      R"({"name": "tube", "linear": [[0.2, 0, 2], [2.6, 0.3, 2.1]], "candela_per_metre": 100})");
  const IlluminanceSolver solver(scene);
  const auto& tube = std::get<LinearLight>(scene.lights[0].source);
  int penumbra_points = 0;
  for (const Vec3d& p :
       {Vec3d{1.0, 0, 0}, Vec3d{1.3, 0.1, 0}, Vec3d{0.7, -0.1, 0}, Vec3d{1.6, 0.05, 0},
        Vec3d{2.0, 0, 0}, Vec3d{1.9, 0.2, 0.3}, Vec3d{1.15, 0.3, 0}}) {
    const auto parts = solver.visible_parts(0, p, {0, 0, 1});
    const double full =
        linear_illuminance(p, {0, 0, 1}, tube.start, tube.end, tube.candela_per_metre);
    const double e = solver.light_at(0, p, {0, 0, 1});
    const bool in_penumbra = e > 0 && e < full * 0.999;
    penumbra_points += in_penumbra;
    const double expected = reference_linear(scene, tube, p, {0, 0, 1}, 20000);
    BOOST_TEST_MESSAGE("penumbra point " << p[0] << "," << p[1] << "," << p[2] << ": E " << e
                                         << ", unshadowed " << full << ", reference " << expected
                                         << ", " << parts.size() << " visible parts");
    BOOST_TEST(close(e, expected, 5e-3), "at (" << p[0] << ", " << p[1] << ", " << p[2]
                                                << "): " << e << " vs " << expected << ", "
                                                << parts.size() << " parts");
  }
  BOOST_TEST(penumbra_points >= 5);
}

// Joint occlusion: from P = (1, 0, 0) the slab at z ~ 0.95 hides the tube (0,0,2)-(2,0,2)
// for u < ~0.56 and the board at z ~ 1.45 hides u > ~0.43, so together they hide all of it
// although neither alone does: E = 0 outside both single umbrae.
BOOST_AUTO_TEST_CASE(joint_occlusion_by_two_occluders_gives_zero) {
  const Scene scene = scene_from(
      R"({"name": "low", "box": {"min": [0.3, -0.5, 0.9], "max": [1.06, 0.5, 1.0]}},
         {"name": "high", "box": {"min": [0.9, -0.5, 1.4], "max": [1.8, 0.5, 1.5]}})",
      R"({"name": "tube", "linear": [[0, 0, 2], [2, 0, 2]], "candela_per_metre": 100})");
  const IlluminanceSolver solver(scene);
  const Vec3d p{1, 0, 0};
  BOOST_TEST(solver.light_at(0, p, {0, 0, 1}) == 0.0);
  BOOST_TEST(solver.visible_parts(0, p, {0, 0, 1}).empty());
  // Exact checks that P is in neither single umbra: each occluder alone leaves an end of
  // the tube visible (the test's own segment oracle), and P is outside each occluder's
  // umbra volume built by the shadow layer (App. A2).
  const Point3 exact_p = to_exact(p), q1(0, 0, 2), q2(2, 0, 2);
  const ConvexPolyhedron& low = scene.objects[0].solid;
  const ConvexPolyhedron& high = scene.objects[1].solid;
  BOOST_TEST(oracle_segment_blocked(low, exact_p, q1));
  BOOST_TEST(!oracle_segment_blocked(low, exact_p, q2));
  BOOST_TEST(oracle_segment_blocked(high, exact_p, q2));
  BOOST_TEST(!oracle_segment_blocked(high, exact_p, q1));
  for (const ConvexPolyhedron* solid : {&low, &high}) {
    const auto volumes = linear_volumes(*solid, q1, q2);
    BOOST_TEST_REQUIRE(volumes.has_value());
    BOOST_TEST(!volumes->umbra.contains(exact_p));
    BOOST_TEST(volumes->penumbra.contains(exact_p));
  }
  // With either occluder alone P is lit, and the values match the exact-visibility reference.
  for (const std::size_t keep : {std::size_t{0}, std::size_t{1}}) {
    Scene single = scene;
    single.objects.erase(single.objects.begin() + static_cast<long>(1 - keep));
    const double e = illuminance_at(single, p, {0, 0, 1}).total;
    BOOST_TEST(e > 0);
    BOOST_TEST(close(e,
                     reference_linear(single, std::get<LinearLight>(scene.lights[0].source), p,
                                      {0, 0, 1}, 20000),
                     5e-3));
  }
}

// Point and directional shadows: a cube on the floor, a lamp and the sun. A point is dark
// exactly when the exact oracle finds the open segment (ray) blocked; points on the shadow
// boundary (the segment grazes an edge) are lit.
BOOST_AUTO_TEST_CASE(point_and_sun_shadows_follow_the_exact_oracle) {
  const Scene scene = scene_from(R"({"name": "cube", "box": {"min": [1, 1, 0], "max": [2, 2, 1]}})",
                                 R"({"name": "bulb", "point": [0, 0, 3], "candela": 300},
         {"name": "sun", "directional": [1, 1, -2], "illuminance": 10000})");
  const IlluminanceSolver solver(scene);
  const ConvexPolyhedron& cube = scene.objects[0].solid;
  int dark_bulb = 0, dark_sun = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Vec3d p{i / 10.0, j / 10.0, 0};
      if (cube.bounded_side(to_exact(p)) != CGAL::ON_UNBOUNDED_SIDE) continue;
      const bool bulb_blocked = oracle_segment_blocked(cube, to_exact(p), Point3(0, 0, 3));
      const bool sun_blocked =
          oracle_meets_interior(cube, to_exact(p), Vector3(-1, -1, 2), std::nullopt);
      const double r2 = p[0] * p[0] + p[1] * p[1] + 9;
      BOOST_TEST(
          solver.light_at(0, p, {0, 0, 1}) == (bulb_blocked ? 0.0 : 300 * 3 / std::sqrt(r2) / r2),
          boost::test_tools::tolerance(1e-12));
      BOOST_TEST(
          solver.light_at(1, p, {0, 0, 1}) == (sun_blocked ? 0.0 : 10000 * 2 / std::sqrt(6.0)),
          boost::test_tools::tolerance(1e-12));
      dark_bulb += bulb_blocked;
      dark_sun += sun_blocked;
    }
  BOOST_TEST(dark_bulb > 20);
  BOOST_TEST(dark_sun > 20);
  // The sun's shadow of the cube's top edge x = 1..2, y = 2, z = 1 falls at y = 2.5 on the
  // floor: (1.5, 2.5, 0) grazes the edge (lit), (1.5, 2.49, 0) is behind it... in shadow.
  BOOST_TEST(solver.light_at(1, {1.5, 2.5, 0}, {0, 0, 1}) > 0);
  BOOST_TEST(solver.light_at(1, {1.5, 2.49, 0}, {0, 0, 1}) == 0.0);
  // A point inside the cube gets nothing and is reported inside.
  const PointIlluminance inside = solver.at({1.5, 1.5, 0.5}, {0, 0, 1});
  BOOST_TEST(inside.total == 0.0);
  BOOST_TEST((inside.inside && *inside.inside == 0u));
}

// Flux conservation: a cardioid lamp I0 (1 + cos g) / 2 (flux 2 pi I0: the integral of
// (1 + cos g) / 2 * 2 pi sin g over g is 2 pi) with a tilted axis inside a closed room of
// six wall slabs, with a cube inside casting shadows on the walls. The light leaving the
// lamp all lands on the room's inner faces or on the cube's outer faces.
BOOST_AUTO_TEST_CASE(flux_is_conserved_in_a_closed_room_with_an_occluder) {
  const Scene scene = scene_from(
      R"({"name": "floor",   "box": {"min": [-0.1, -0.1, -0.1], "max": [4.1, 3.1, 0]}},
         {"name": "ceiling", "box": {"min": [-0.1, -0.1, 2.5], "max": [4.1, 3.1, 2.6]}},
         {"name": "west",    "box": {"min": [-0.1, -0.1, 0], "max": [0, 3.1, 2.5]}},
         {"name": "east",    "box": {"min": [4, -0.1, 0], "max": [4.1, 3.1, 2.5]}},
         {"name": "south",   "box": {"min": [0, -0.1, 0], "max": [4, 0, 2.5]}},
         {"name": "north",   "box": {"min": [0, 3, 0], "max": [4, 3.1, 2.5]}},
         {"name": "cube",    "box": {"min": [2.2, 1.2, 0.6], "max": [2.8, 1.8, 1.2]}})",
      R"({"name": "lamp", "point": [1.3, 1.1, 1.7], "axis": [0.3, -0.2, -0.93],
          "lid": {"cardioid": true, "candela": 500}})");
  const IlluminanceSolver solver(scene);
  const double emitted = 2 * pi * 500;
  // Room: inner faces, normals into the room; 2 cm panels with 2 x 2 Gauss points (the
  // shadow edges on the walls are where the rule is least accurate: its error there is
  // about jump x edge length x panel size, well under 0.1% here).
  const double room =
      flux_on_rectangle(solver, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, {0, 0, 1}, 200, 150) +
      flux_on_rectangle(solver, {0, 0, 2.5}, {4, 0, 0}, {0, 3, 0}, {0, 0, -1}, 200, 150) +
      flux_on_rectangle(solver, {0, 0, 0}, {0, 3, 0}, {0, 0, 2.5}, {1, 0, 0}, 150, 125) +
      flux_on_rectangle(solver, {4, 0, 0}, {0, 3, 0}, {0, 0, 2.5}, {-1, 0, 0}, 150, 125) +
      flux_on_rectangle(solver, {0, 0, 0}, {4, 0, 0}, {0, 0, 2.5}, {0, 1, 0}, 200, 125) +
      flux_on_rectangle(solver, {0, 3, 0}, {4, 0, 0}, {0, 0, 2.5}, {0, -1, 0}, 200, 125);
  // Cube: outer faces (those turned away from the lamp receive 0 by the tie-break).
  const double c = 0.6;
  const double cube =
      flux_on_rectangle(solver, {2.2, 1.2, 0.6}, {c, 0, 0}, {0, c, 0}, {0, 0, -1}, 30, 30) +
      flux_on_rectangle(solver, {2.2, 1.2, 1.2}, {c, 0, 0}, {0, c, 0}, {0, 0, 1}, 30, 30) +
      flux_on_rectangle(solver, {2.2, 1.2, 0.6}, {0, c, 0}, {0, 0, c}, {-1, 0, 0}, 30, 30) +
      flux_on_rectangle(solver, {2.8, 1.2, 0.6}, {0, c, 0}, {0, 0, c}, {1, 0, 0}, 30, 30) +
      flux_on_rectangle(solver, {2.2, 1.2, 0.6}, {c, 0, 0}, {0, 0, c}, {0, -1, 0}, 30, 30) +
      flux_on_rectangle(solver, {2.2, 1.8, 0.6}, {c, 0, 0}, {0, 0, c}, {0, 1, 0}, 30, 30);
  BOOST_TEST_MESSAGE("flux: room " << room << " + cube " << cube << " = " << room + cube
                                   << " lm, emitted " << emitted << " lm");
  BOOST_TEST(cube > 0.01 * emitted);  // the cube does intercept a noticeable share
  BOOST_TEST(close(room + cube, emitted, 1e-3),
             "room " << room << " + cube " << cube << " vs " << emitted);
}

BOOST_AUTO_TEST_SUITE_END()
