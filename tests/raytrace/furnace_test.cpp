#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/raytrace/ray_tracer.h"
#include "penumbra/scene/scene.h"
#include "scene_support.h"

// Furnace tests (after pbrt's): a closed sphere of radius R around an isotropic lamp of I cd
// at its centre. Every point of the inside receives E = I / R^2 at normal incidence, so its
// diffuse luminance is L0 = rho E / pi everywhere. With mirror weight k_s, a ray from any
// point inside reaches a sphere point whose mirror ray reaches another sphere point of the
// same kind, so the ray tree sums a geometric series: L = L0 (1 + k_s + ... + k_s^N) for a
// tree cut at depth N, L0 / (1 - k_s) in the limit.

namespace {

using penumbra::Vec3d;
using namespace penumbra::raytrace;

using penumbra::pi;
const double radius = 2, candela = 50, rho = 0.3, k_s = 0.6;

penumbra::Scene furnace_scene() {
  return penumbra::test::scene_from_json("furnace", R"({"penumbra": 1,
    "materials": {"inside": {"reflectance": 0.3, "reflect": 0.6}},
    "objects": [{"name": "shell", "sphere": {"center": [0, 0, 0], "radius": 2}, "material": "inside"}],
    "lights": [{"name": "bulb", "point": [0, 0, 0], "candela": 50}]})");
}

double partial_sum(int terms_after_first, double ratio) {
  double sum = 0, term = 1;
  for (int k = 0; k <= terms_after_first; ++k, term *= ratio) sum += term;
  return sum;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(furnace)

BOOST_AUTO_TEST_CASE(the_ray_tree_sums_the_geometric_series_of_interreflection) {
  const penumbra::Scene scene = furnace_scene();
  const double l0 = rho * (candela / (radius * radius)) / pi;
  const Vec3d eyes[] = {{0.5, 0.3, -0.2}, {-1.2, 0.4, 0.9}};
  const Vec3d directions[] = {{1, 0, 0}, {0.3, -0.8, 0.5}, {-0.2, 0.1, -1}};
  for (int depth : {0, 1, 3, 8}) {
    TraceOptions options;
    options.max_depth = depth;
    options.min_weight = 0;  // let depth alone cut the tree
    const RayTracer tracer(scene, options);
    for (const Vec3d& eye : eyes)
      for (const Vec3d& direction : directions) {
        RayCounts counts;
        const double value = tracer.trace(eye, direction, 3, counts).radiance[0];
        BOOST_TEST(std::abs(value - l0 * partial_sum(depth, k_s)) < 1e-9 * l0);
        BOOST_TEST(counts.reflected == static_cast<unsigned>(depth));
      }
  }
}

BOOST_AUTO_TEST_CASE(the_weight_threshold_cuts_the_tree_where_k_s_to_the_k_falls_below_it) {
  // Depth 40 with threshold 1e-3: the generation-k ray is cast while k_s^k >= 1e-3, that is
  // for k <= floor(ln 1e-3 / ln 0.6) = 13.
  TraceOptions options;
  options.max_depth = 40;
  options.min_weight = 1e-3;
  const int last = static_cast<int>(std::floor(std::log(1e-3) / std::log(k_s)));
  BOOST_TEST(last == 13);
  const penumbra::Scene scene = furnace_scene();
  const RayTracer tracer(scene, options);
  RayCounts counts;
  const double value = tracer.trace({0.1, 0.2, 0.3}, {0, 1, 0}, 3, counts).radiance[0];
  const double l0 = rho * (candela / (radius * radius)) / pi;
  BOOST_TEST(std::abs(value - l0 * partial_sum(last, k_s)) < 1e-9 * l0);
  BOOST_TEST(counts.reflected == static_cast<unsigned>(last));
}

BOOST_AUTO_TEST_CASE(linear_attenuation_scales_each_generation_by_its_chord) {
  // From the centre every ray is a diameter (2R); linear attenuation uses the scene
  // diagonal D = 2R sqrt(3) (the box around the sphere), so each generation is weighted by
  // k_s (1 - 2R / D) = k_s (1 - 1 / sqrt(3)); the camera ray itself is not attenuated (it has
  // no parent node, section 2).
  TraceOptions options;
  options.max_depth = 8;
  options.min_weight = 0;
  options.attenuation = Attenuation::linear;
  const penumbra::Scene scene = furnace_scene();
  const RayTracer tracer(scene, options);
  RayCounts counts;
  const double value = tracer.trace({0, 0, 0}, {0.6, 0, 0.8}, 3, counts).radiance[0];
  const double l0 = rho * (candela / (radius * radius)) / pi;
  const double ratio = k_s * (1 - 1 / std::sqrt(3.0));
  BOOST_TEST(std::abs(value - l0 * partial_sum(8, ratio)) < 1e-9 * l0);
}

BOOST_AUTO_TEST_SUITE_END()
