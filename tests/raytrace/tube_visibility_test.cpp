#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/raytrace/ray_tracer.h"
#include "penumbra/raytrace/tube_visibility.h"
#include "penumbra/scene/camera_frame.h"
#include "penumbra/scene/scene.h"
#include "scene_support.h"

// The ray tracer's diffuse term from a tube: the closed form over the exactly visible pieces
// (Nishita 1985 section 4.2.3), transparent occluders passing k_t per surface crossed.
//
// Every scene has the tube A = (-1, 0, 2) -> B = (1, 0, 2), I = 100 cd/m, over a floor box
// whose top is z = 0 (reflectance 0.6), so a floor point shows 0.6 E / pi.

namespace {

using penumbra::CameraFrame;
using penumbra::Vec3d;
using namespace penumbra::raytrace;
using penumbra::test::scene_from_json;
namespace tt = boost::test_tools;

using penumbra::pi;
const Vec3d tube_start{-1, 0, 2}, tube_end{1, 0, 2}, up{0, 0, 1};

const std::string tube_and_floor = R"(
    "lights": [{"name": "tube", "linear": [[-1, 0, 2], [1, 0, 2]], "candela_per_metre": 100}],
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [3, 3, 0]}, "material": "paint"})";

// the closed form of illuminance/linear_source.h over one parameter interval [low, high].
double closed_form(const Vec3d& point, double low, double high) {
  return penumbra::illuminance::linear_illuminance(point, up, tube_start, tube_end, 100,
                                                   {{low, high}});
}

// the luminance seen along the ray from eye toward target.
double luminance_toward(const RayTracer& tracer, const Vec3d& eye, const Vec3d& target) {
  RayCounts counts;
  const Vec3d toward{target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
  const TraceResult seen = tracer.trace(eye, toward, 3, counts);
  BOOST_REQUIRE(seen.object == std::optional<std::size_t>(0));  // the floor
  return seen.radiance[0];
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tube_visibility)

BOOST_AUTO_TEST_CASE(an_opaque_box_gives_the_exact_engines_penumbra_at_every_pixel) {
  const auto scene = scene_from_json("tube-opaque", R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.6}},)" + tube_and_floor +
                                                        R"(,
      {"name": "block", "box": {"min": [0.2, -0.5, 0.9], "max": [1.5, 0.5, 1.1]}, "material": "paint"}],
    "camera": {"eye": [0, -3, 3], "target": [0.3, 0, 0], "up": [0, 0, 1], "fov_deg": 50,
               "width": 48, "height": 36}})");
  const RayTracer tracer(scene);
  const penumbra::illuminance::IlluminanceSolver solver(scene);
  const CameraFrame camera(*scene.camera);
  int lit = 0, penumbra = 0, umbra = 0;
  for (int j = 0; j < camera.height(); ++j)
    for (int i = 0; i < camera.width(); ++i) {
      const Vec3d direction = camera.unit_direction(i + 0.5, j + 0.5);
      const auto hit = tracer.embree_scene().intersect({camera.eye(), direction});
      if (!hit || hit->object != 0) continue;
      // The exact engine at the floor point (z = 0 exactly: the hit point is rounded and
      // may lie a few ulps inside the floor, where the engine would give 0).
      const Vec3d q{hit->point[0], hit->point[1], 0};
      const double e = solver.at(q, up).total;
      const double unoccluded =
          penumbra::illuminance::linear_illuminance(q, up, tube_start, tube_end, 100);
      RayCounts counts;
      const double seen = tracer.trace(camera.eye(), direction, 1, counts).radiance[0];
      BOOST_TEST(seen == 0.6 * e / pi, tt::tolerance(1e-9));
      BOOST_TEST(counts.shadow == 0u);  // the tube needs no shadow rays
      if (e == 0)
        ++umbra;
      else if (e < unoccluded * (1 - 1e-6))
        ++penumbra;
      else
        ++lit;
    }
  BOOST_TEST(penumbra > 20);
  BOOST_TEST(lit > 20);
  BOOST_TEST_MESSAGE("lit " << lit << ", penumbra " << penumbra << ", umbra " << umbra);
}

// A glass box x in [0.25, 3], y in [-1, 1], z in [0.9, 1] with k_t = 0.5. From the floor
// point P = (p, 0, 0) the segment to the tube element (x, 0, 2) is at height z over
// p + (x - p) z / 2; for x > p this grows with z, so it enters the box's interior iff its
// value at the top z = 1 exceeds 0.25: x > 0.5 - p, i.e. u = (x + 1) / 2 > (1.5 - p) / 2.
// That part crosses two surfaces and passes k_t^2 = 0.25.
BOOST_AUTO_TEST_CASE(a_transparent_box_passes_kt_squared_of_the_part_behind_it) {
  const std::string glass_box = R"(,
      {"name": "glass", "box": {"min": [0.25, -1, 0.9], "max": [3, 1, 1]}, "material": "glass"})";
  const std::string materials = R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.6}, "glass": {"reflectance": 0, "transmit": 0.5}},)";
  const auto scene = scene_from_json("tube-glass", materials + tube_and_floor + glass_box + "]}");
  const RayTracer tracer(scene);
  const Vec3d eye{-1.5, -1, 1};  // sees the floor points past the glass
  for (double p : {0.0, 0.2}) {
    const double cut = (1.5 - p) / 2;  // 0.75, 0.65
    const Vec3d point{p, 0, 0};
    const double e = closed_form(point, 0, cut) + 0.25 * closed_form(point, cut, 1);
    BOOST_TEST(luminance_toward(tracer, eye, point) == 0.6 * e / pi, tt::tolerance(1e-9));
    // The pieces themselves.
    const TubeVisibility visibility(scene, 1e-3);
    const auto pieces = visibility.pieces(0, point, up);
    BOOST_REQUIRE(pieces.size() == 2u);
    BOOST_TEST(pieces[0].low == 0.0);
    BOOST_TEST(pieces[0].high == cut, tt::tolerance(1e-15));
    BOOST_TEST(pieces[0].passed == 1.0);
    BOOST_TEST(pieces[1].low == cut, tt::tolerance(1e-15));
    BOOST_TEST(pieces[1].high == 1.0);
    BOOST_TEST(pieces[1].passed == 0.25);
  }

  // Add a glass pane (a flat polygon: one surface, k_t = 0.5) at z = 0.5 over x >= 0.1. From
  // the origin the element (x, 0, 2) is seen through it where x / 4 > 0.1: u > 0.7. The
  // pieces [0, 0.7], [0.7, 0.75], [0.75, 1] pass 1, 0.5 and 0.5 * 0.25.
  const std::string pane = R"(,
      {"name": "pane", "polygon": [[0.1, -1, 0.5], [3, -1, 0.5], [3, 1, 0.5], [0.1, 1, 0.5]], "material": "glass"})";
  const auto both =
      scene_from_json("tube-glass-pane", materials + tube_and_floor + glass_box + pane + "]}");
  const RayTracer through_both(both);
  const Vec3d origin{0, 0, 0};
  const double e = closed_form(origin, 0, 0.7) + 0.5 * closed_form(origin, 0.7, 0.75) +
                   0.125 * closed_form(origin, 0.75, 1);
  BOOST_TEST(luminance_toward(through_both, eye, origin) == 0.6 * e / pi, tt::tolerance(1e-9));

  // An opaque material in place of the glass hides the part behind the box entirely.
  const auto opaque = scene_from_json("tube-opaque-box", R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.6}, "glass": {"reflectance": 0}},)" +
                                                             tube_and_floor + glass_box + "]}");
  BOOST_TEST(
      luminance_toward(RayTracer(opaque), eye, origin) == 0.6 * closed_form(origin, 0, 0.75) / pi,
      tt::tolerance(1e-9));
}

// Seen from inside a glass solid the light crosses the solid's one surface (as a shadow ray
// from there would). A glass box z in [0.9, 1] (k_t = 0.5, ior 1 so rays pass unbent,
// reflectance 0.4) over the tube (0.5, 0, 0.5) -> (1.5, 0, 0.5). A ray straight up from
// (1, -0.3, 0.2) meets the bottom face from outside at P1 = (1, -0.3, 0.9), facing normal
// -z: the tube lights it directly, E1. The transmitted ray (k_t) meets the top face from
// inside at P2 = (1, -0.3, 1), facing normal -z again, pointing into the box: the whole
// tube lies on that side, seen through the bottom face, so E2 passes k_t once (not k_t^2,
// as for a box seen from outside). The ray then leaves into the black background. So
//     L = 0.4 E1 / pi + k_t 0.4 (k_t E2) / pi.
BOOST_AUTO_TEST_CASE(inside_a_glass_solid_the_tube_passes_kt_once) {
  const auto scene = scene_from_json("tube-inside", R"({"penumbra": 1,
    "materials": {"glass": {"reflectance": 0.4, "transmit": 0.5, "ior": 1}},
    "lights": [{"name": "tube", "linear": [[0.5, 0, 0.5], [1.5, 0, 0.5]], "candela_per_metre": 100}],
    "objects": [{"name": "glass", "box": {"min": [0.25, -1, 0.9], "max": [3, 1, 1]}, "material": "glass"}]})");
  const RayTracer tracer(scene);
  const auto e_at = [](const Vec3d& point) {
    return penumbra::illuminance::linear_illuminance(point, {0, 0, -1}, {0.5, 0, 0.5},
                                                     {1.5, 0, 0.5}, 100);
  };
  const double e1 = e_at({1, -0.3, 0.9}), e2 = e_at({1, -0.3, 1});
  RayCounts counts;
  const TraceResult seen = tracer.trace({1, -0.3, 0.2}, {0, 0, 1}, 1, counts);
  BOOST_REQUIRE(seen.object == std::optional<std::size_t>(0));
  BOOST_TEST(counts.refracted == 2u);
  BOOST_TEST(seen.radiance[0] == 0.4 * e1 / pi + 0.5 * 0.4 * (0.5 * e2) / pi, tt::tolerance(1e-9));
}

// Phong's highlight from a tube is sampled within the exact pieces. Seen from straight above
// (to_viewer = N) with shininess 1, cos(psi) = (2 cos(alpha) N - L) . N = cos(alpha), so the
// highlight (k_spec / pi) sum E_n cos(psi) is k_spec / pi times the stratified estimate of E:
// with the glass box above, (k_spec / pi) (E(visible) + k_t^2 E(behind)) up to the sampling
// error (the integrand is smooth within each piece: far below 1e-4 with 4096 strata).
BOOST_AUTO_TEST_CASE(the_tubes_highlight_is_sampled_within_the_weighted_pieces) {
  const auto scene = scene_from_json("tube-highlight", R"({"penumbra": 1,
    "materials": {"gloss": {"reflectance": 0, "specular": 0.5, "shininess": 1},
                  "paint": {"reflectance": 0.6}, "glass": {"reflectance": 0, "transmit": 0.5}},
    "lights": [{"name": "tube", "linear": [[-1, 0, 2], [1, 0, 2]], "candela_per_metre": 100}],
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [3, 3, 0]}, "material": "gloss"},
      {"name": "glass", "box": {"min": [0.25, -1, 0.9], "max": [3, 1, 1]}, "material": "glass"}]})");
  TraceOptions options;
  options.tube_samples = 4096;
  const RayTracer tracer(scene, options);
  const Vec3d origin{0, 0, 0};
  const double e = closed_form(origin, 0, 0.75) + 0.25 * closed_form(origin, 0.75, 1);
  RayCounts counts;
  const TraceResult seen = tracer.trace({0, 0, 1}, {0, 0, -1}, 5, counts);
  BOOST_TEST(seen.radiance[0] == 0.5 * e / pi, tt::tolerance(1e-4));
  BOOST_TEST(counts.shadow == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
