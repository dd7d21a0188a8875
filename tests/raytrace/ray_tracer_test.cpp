#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/point_source.h"
#include "penumbra/raytrace/ray_tracer.h"
#include "penumbra/scene/scene.h"
#include "scene_support.h"

namespace {

using penumbra::Vec3d;
using namespace penumbra::raytrace;
using penumbra::test::scene_from_json;

namespace tt = boost::test_tools;
using penumbra::pi;

Vec3d minus(const Vec3d& a, const Vec3d& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double norm(const Vec3d& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// traces one camera ray from eye toward target.
TraceResult look(const RayTracer& tracer, const Vec3d& eye, const Vec3d& target) {
  RayCounts counts;
  return tracer.trace(eye, minus(target, eye), 7, counts);
}

// E = I cos(alpha) / r^2 on the floor z = 0 (normal +z) at q from an isotropic lamp.
double floor_illuminance(const Vec3d& lamp, double candela, const Vec3d& q) {
  const Vec3d to_lamp = minus(lamp, q);
  const double r = norm(to_lamp);
  return candela * (to_lamp[2] / r) / (r * r);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ray_tracer)

BOOST_AUTO_TEST_CASE(a_diffuse_plane_has_radiance_rho_e_over_pi) {
  const auto scene = scene_from_json("diffuse", R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.6, "color": [1, 0.5, 0.25]}},
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [3, 3, 0]}, "material": "paint"}],
    "lights": [{"name": "bulb", "point": [0.3, -0.2, 2], "candela": 100}]})");
  const RayTracer tracer(scene);
  const Vec3d q{-0.4, 0.5, 0};
  const TraceResult seen = look(tracer, {1, 1, 1.5}, q);
  const double e = floor_illuminance({0.3, -0.2, 2}, 100, q);
  // The illuminance layer agrees with the hand derivation.
  BOOST_TEST(penumbra::illuminance::point_illuminance(q, {0, 0, 1}, {0.3, -0.2, 2}, 100.0) == e,
             tt::tolerance(1e-14));
  BOOST_REQUIRE(seen.object.has_value());
  BOOST_TEST(seen.radiance[0] == 0.6 * e / pi, tt::tolerance(1e-9));
  BOOST_TEST(seen.radiance[1] == 0.6 * 0.5 * e / pi, tt::tolerance(1e-9));
  BOOST_TEST(seen.radiance[2] == 0.6 * 0.25 * e / pi, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(lamp_distributions_and_the_sun_enter_as_illuminance) {
  // A lamp pointing down with the table I(gamma) = 100 - 50 gamma / 90 deg (linear
  // interpolation between 0, 90 and 180 degrees), and a sun along (1, 0, -2) giving 1000 lux
  // on a plane normal to it.
  const auto scene = scene_from_json("distribution", R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.5}},
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [3, 3, 0]}, "material": "paint"}],
    "lights": [{"name": "lamp", "point": [0, 0, 2], "axis": [0, 0, -1],
                "lid": {"table_deg": [0, 90, 180], "candela": [100, 50, 0], "interpolation": "linear"}},
               {"name": "sun", "directional": [1, 0, -2], "illuminance": 1000}]})");
  const RayTracer tracer(scene);
  const Vec3d q{1.5, 0.5, 0};
  const double r = norm(minus({0, 0, 2}, q));
  const double gamma_deg = std::acos(2 / r) * 180 / pi;
  const double candela = 100 - 50 * gamma_deg / 90;
  const double e = candela * (2 / r) / (r * r) + 1000 * 2 / std::sqrt(5.0);
  BOOST_TEST(look(tracer, {-1, -1, 1}, q).radiance[0] == 0.5 * e / pi, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_blocked_shadow_ray_removes_the_light) {
  const auto scene = scene_from_json("shadow", R"({"penumbra": 1,
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [3, 3, 0]}},
                {"name": "card", "polygon": [[-0.5, -0.5, 1], [0.5, -0.5, 1], [0.5, 0.5, 1], [-0.5, 0.5, 1]]}],
    "lights": [{"name": "bulb", "point": [0, 0, 2], "candela": 100}]})");
  const RayTracer tracer(scene);
  // Under the card (its shadow on the floor is |x|, |y| < 1) and outside it.
  BOOST_TEST(look(tracer, {2, 2, 0.5}, {0.3, 0.2, 0}).radiance[0] == 0.0);
  const Vec3d lit{1.5, -1.2, 0};
  BOOST_TEST(look(tracer, {2, 2, 0.5}, lit).radiance[0] ==
                 0.5 * floor_illuminance({0, 0, 2}, 100, lit) / pi,
             tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_perfect_mirror_shows_the_radiance_of_the_reflected_point) {
  // A mirror in the plane x = 2; the eye at (0, 0, 1.5) sees the floor point q = (1, 0.3, 0)
  // where the line from its mirror image (4, 0, 1.5) to q crosses x = 2: at s = 2/3,
  // m = (2, 0.2, 0.5).
  const auto scene = scene_from_json("mirror", R"({"penumbra": 1,
    "materials": {"mirror": {"reflectance": 0, "reflect": 1}, "paint": {"reflectance": 0.5}},
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [1.9, 3, 0]}, "material": "paint"},
                {"name": "mirror", "polygon": [[2, -2, 0.2], [2, 2, 0.2], [2, 2, 3], [2, -2, 3]], "material": "mirror"}],
    "lights": [{"name": "bulb", "point": [0, 0, 3], "candela": 200}]})");
  const RayTracer tracer(scene);
  const TraceResult seen = look(tracer, {0, 0, 1.5}, {2, 0.2, 0.5});
  BOOST_TEST(seen.radiance[0] == 0.5 * floor_illuminance({0, 0, 3}, 200, {1, 0.3, 0}) / pi,
             tt::tolerance(1e-9));
  BOOST_TEST(*seen.object == 1u);  // the first hit is the mirror itself
}

// returns the camera offset x0 at which a ray from (x0, 0, 3) along (sin t, 0, -cos t) moves
// from the white floor (x < 0) to the black floor (x > 0), by bisection on the radiance.
double edge_offset(const RayTracer& tracer, double theta) {
  double white = -5, black = 1;  // offsets seeing white and black
  const Vec3d direction{std::sin(theta), 0, -std::cos(theta)};
  for (int step = 0; step < 50; ++step) {
    const double middle = (white + black) / 2;
    RayCounts counts;
    const double value = tracer.trace({middle, 0, 3}, direction, 1, counts).radiance[0];
    (value > 0 ? white : black) = middle;
  }
  return (white + black) / 2;
}

BOOST_AUTO_TEST_CASE(a_clear_slab_displaces_the_image_by_snells_amount) {
  // A glass slab 0.5 thick (z in [1, 1.5], n = 1.5, k_t = 1) over a floor that is white for
  // x < 0 and black for x > 0, lit by a lamp under the slab. A ray at angle t crosses 1.5 m of
  // air above the slab, 0.5 m of glass at t_t (sin t = 1.5 sin t_t) and 1 m of air below, so
  // the edge x = 0 is seen from x0 = -(2.5 tan t + 0.5 tan t_t); without the slab from
  // x0 = -3 tan t.
  const std::string floor = R"(
    "materials": {"white": {"reflectance": 0.8}, "black": {"reflectance": 0},
                  "glass": {"reflectance": 0, "transmit": 1, "ior": 1.5}},
    "lights": [{"name": "bulb", "point": [0, 3, 0.8], "candela": 100}],)";
  const std::string floor_objects = R"(
    {"name": "white", "box": {"min": [-6, -6, -0.1], "max": [0, 6, 0]}, "material": "white"},
    {"name": "black", "box": {"min": [0, -6, -0.1], "max": [6, 6, 0]}, "material": "black"})";
  const auto bare = scene_from_json(
      "no-slab", R"({"penumbra": 1,)" + floor + R"("objects": [)" + floor_objects + "]}");
  const auto slab = scene_from_json(
      "slab",
      R"({"penumbra": 1,)" + floor + R"("objects": [)" + floor_objects +
          R"(, {"name": "slab", "box": {"min": [-6, -6, 1], "max": [6, 6, 1.5]}, "material": "glass"}]})");
  const RayTracer without(bare), with(slab);
  // Which of the two abutting floor boxes a ray near x = 0 meets is decided by Embree in
  // single precision (about 1e-6 m at these coordinates); the displacements are 0.1 to 0.6 m.
  for (double theta : {0.3, 0.6, 0.9}) {
    const double theta_t = std::asin(std::sin(theta) / 1.5);
    BOOST_TEST(std::abs(edge_offset(without, theta) + 3 * std::tan(theta)) < 1e-5);
    BOOST_TEST(std::abs(edge_offset(with, theta) +
                        (2.5 * std::tan(theta) + 0.5 * std::tan(theta_t))) < 1e-5);
  }
}

BOOST_AUTO_TEST_CASE(total_internal_reflection_stops_transmission_or_reflects_all) {
  // A right prism (cross-section (0,0), (1,0), (0,1) in x-z) of glass n = 1.5 with k_t = 1,
  // k_s = 0. A ray along +x at z = 0.3 enters the leg x = 0 normally and meets the hypotenuse
  // x + z = 1 at 45 degrees, beyond the critical angle asin(1 / 1.5) = 41.8 degrees.
  // Constant k_s = 0: the paper sets T = 0 under total internal reflection and nothing else
  // returns. With --fresnel the hypotenuse reflects everything (F = 1) down through the leg
  // z = 0 at normal incidence onto the floor: both crossings pass 1 - F(0) = 1 - f with
  // f = ((n - 1) / (n + 1))^2 = 0.04. The part f reflected inside at z = 0 goes up, is
  // totally reflected toward x = 0, where f returns it (1 - f leaves into the black
  // background), and it comes down the same way to the floor: each loop adds a factor f^2.
  // The tree keeps the first loop (weight (1 - f)^2 f^2 = 1.5e-3) and drops the second
  // (below the threshold 1e-3), so the floor's radiance arrives scaled by
  // (1 - f)^2 (1 + f^2). Other branches end in the black background.
  const auto scene = scene_from_json("prism", R"({"penumbra": 1,
    "materials": {"glass": {"reflectance": 0, "transmit": 1, "ior": 1.5}, "paint": {"reflectance": 0.5}},
    "objects": [{"name": "prism", "convex": [[0, -1, 0], [1, -1, 0], [0, -1, 1], [0, 1, 0], [1, 1, 0], [0, 1, 1]],
                 "material": "glass"},
                {"name": "floor", "box": {"min": [-3, -3, -1.1], "max": [3, 3, -1]}, "material": "paint"},
                {"name": "wall", "box": {"min": [3, -3, -1], "max": [3.1, 3, 2]}, "material": "paint"}],
    "lights": [{"name": "bulb", "point": [2, 0, -0.5], "candela": 100}]})");
  const Vec3d eye{-1, 0, 0.3}, along{1, 0, 0};
  RayCounts counts;
  const RayTracer constant(scene);
  BOOST_TEST(constant.trace(eye, along, 1, counts).radiance[0] == 0.0);
  TraceOptions fresnel;
  fresnel.fresnel = true;
  const RayTracer physical(scene, fresnel);
  const double floor_radiance = 0.5 * floor_illuminance({2, 0, 0.5}, 100, {0.7, 0, 0}) / pi;
  BOOST_TEST(physical.trace(eye, along, 1, counts).radiance[0] ==
                 0.96 * 0.96 * (1 + 0.04 * 0.04) * floor_radiance,
             tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(rough_mirrors_scatter_reproducibly) {
  // Section 2's microfacets: a rough mirror's reflected ray depends on the perturbed normal,
  // drawn from the sample's seed: the same sample gives the same value, other samples
  // others, and their mean stays near the sharp mirror's (the floor's luminance varies
  // smoothly around the reflected point).
  const std::string objects = R"(
    "objects": [{"name": "floor", "box": {"min": [-3, -3, -0.1], "max": [1.9, 3, 0]}, "material": "paint"},
                {"name": "mirror", "polygon": [[2, -2, 0.2], [2, 2, 0.2], [2, 2, 3], [2, -2, 3]], "material": "mirror"}],
    "lights": [{"name": "bulb", "point": [0, 0, 3], "candela": 200}]})";
  const auto rough = scene_from_json("rough", R"({"penumbra": 1,
    "materials": {"mirror": {"reflectance": 0, "reflect": 1, "roughness": 0.05}, "paint": {"reflectance": 0.5}},)" +
                                                  objects);
  const RayTracer tracer(rough);
  RayCounts counts;
  const Vec3d eye{0, 0, 1.5}, toward{2, 0.2, -1};
  const double first = tracer.trace(eye, toward, 11, counts).radiance[0];
  BOOST_TEST(tracer.trace(eye, toward, 11, counts).radiance[0] == first);
  double sum = 0;
  int differing = 0;
  for (std::uint64_t key = 0; key < 200; ++key) {
    const double value = tracer.trace(eye, toward, key, counts).radiance[0];
    sum += value;
    if (value != first) ++differing;
  }
  BOOST_TEST(differing > 190);
  const double sharp = 0.5 * floor_illuminance({0, 0, 3}, 200, {1, 0.3, 0}) / pi;
  BOOST_TEST(sum / 200 == sharp, tt::tolerance(0.05));
}

BOOST_AUTO_TEST_SUITE_END()
