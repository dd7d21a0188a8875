#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/raytrace/area_sampling.h"
#include "penumbra/scene/load_scene.h"

// Stratified shadow rays over an area source (the ray tracer's estimate) against the exact
// engine's value (Lambert's closed form over the exactly visible part). The panel is the 1 m x
// 1 m panel of CIE 171:2006 test 5.3 (1000 cd/m^2 at z = 3); a box hides part of it from some
// points. The transmittance of each shadow ray is decided exactly (the box is convex: the
// segment meets its interior when its parameter interval inside the slabs is not empty).

namespace {

using namespace penumbra;

const char* kScene = R"({"penumbra": 1,
  "objects": [{"name": "box", "box": {"min": [1.7, 1.6, 1.5], "max": [2.4, 2.3, 1.8]}}],
  "lights": [{"name": "panel", "area": [[1.5,1.5,3],[1.5,2.5,3],[2.5,2.5,3],[2.5,1.5,3]],
              "luminance": 1000}]})";

// returns true when the open segment p -> q meets the open box (slabs, in doubles: the test
// points keep far from the box's shadow edges at the tolerance asked).
bool blocked(const Vec3d& p, const Vec3d& q) {
  const Vec3d low{1.7, 1.6, 1.5}, high{2.4, 2.3, 1.8};
  double t0 = 0, t1 = 1;
  for (int i = 0; i < 3; ++i) {
    const double d = q[i] - p[i];
    if (d == 0) {
      if (p[i] <= low[i] || p[i] >= high[i]) return false;
      continue;
    }
    double a = (low[i] - p[i]) / d, b = (high[i] - p[i]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 < t1;
}

double estimate(const AreaLight& panel, const Vec3d& p, int samples, std::uint64_t seed) {
  double e = 0;
  for (const raytrace::SourceElement& element : raytrace::sample_area_stratified(
           panel, p, samples, seed, [&](const Vec3d& q) { return blocked(p, q) ? 0.0 : 1.0; })) {
    const Vec3d d{element.position[0] - p[0], element.position[1] - p[1],
                  element.position[2] - p[2]};
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    e += element.candela * (d[2] / std::sqrt(r2)) / r2;  // normal +z
  }
  return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(area_sampling)

// With 16,384 strata the estimate's error is a few 1e-4 where the panel is wholly seen (a
// smooth integrand: jittered strata err as n^-1) and about 1e-3 where a shadow edge crosses
// it (the strata it cuts, measured); the bound, 5e-3, leaves a factor of about 4. In umbra
// both are 0.
BOOST_AUTO_TEST_CASE(stratified_shadow_rays_converge_to_the_exact_value) {
  const Scene scene = parse_scene(kScene, "area-sampling.json");
  const illuminance::IlluminanceSolver solver(scene);
  const auto& panel = std::get<AreaLight>(scene.lights[0].source);
  for (const Vec3d& p : {Vec3d{2, 2, 0}, Vec3d{0.5, 3.1, 0}, Vec3d{1.4, 2.2, 0}, Vec3d{3, 1, 0}}) {
    const double exact = solver.at(p, {0, 0, 1}).total;
    const double sampled = estimate(panel, p, 16384, 7);
    BOOST_TEST(std::abs(sampled - exact) <= 5e-3 * exact,
               p[0] << "," << p[1] << ": " << sampled << " against " << exact);
  }
  // Behind a one-sided panel: nothing.
  BOOST_TEST(estimate(panel, {2, 2, 4}, 64, 1) == 0);
}

BOOST_AUTO_TEST_SUITE_END()
