#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/illuminance/scene_illuminance.h"
#include "penumbra/raytrace/ray_tracer.h"
#include "penumbra/raytrace/tube_sampling.h"
#include "penumbra/scene/scene.h"
#include "scene_support.h"

// Illuminance from a linear source in penumbra, ray traced with stratified samples, against
// an independent integration of Nishita's eq. (5) written here.
//
// The tube runs from (-1, 0, 2) to (1, 0, 2) with I = 100 cd/m; the receiver is the origin,
// normal +z. An element at (x, 0, 2) is at r^2 = x^2 + 4, sees the receiver at sin(theta) =
// 2 / r from the tube's axis and lights it at cos(alpha) = 2 / r, so
//     E = I * integral of 4 / (x^2 + 4)^2 dx over the visible part.
// A card in the plane z = 1 covering x >= 0.25 hides the elements with x / 2 >= 0.25: the
// visible part is x in [-1, 0.5].

namespace {

using namespace penumbra::raytrace;

// composite Simpson's rule with n (even) intervals.
double simpson(double a, double b, int n, double (*f)(double)) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * f(a + k * h);
  return sum * h / 3;
}

double integrand(double x) {
  return 100 * 4 / ((x * x + 4) * (x * x + 4));
}

// returns the illuminance at receiver (normal +z) estimated from `samples` stratified elements
// of the tube with one shadow ray each (Embree), counting the rays in shadow_rays.
double stratified_estimate(const RayTracer& tracer, const penumbra::LinearLight& tube,
                           const penumbra::Vec3d& receiver, int samples, std::uint64_t seed,
                           int& shadow_rays) {
  const auto elements =
      sample_tube_stratified(tube, receiver, samples, seed, [&](const penumbra::Vec3d& position) {
        ++shadow_rays;
        penumbra::Vec3d toward{position[0] - receiver[0], position[1] - receiver[1],
                               position[2] - receiver[2]};
        const double distance =
            std::sqrt(toward[0] * toward[0] + toward[1] * toward[1] + toward[2] * toward[2]);
        for (double& c : toward) c /= distance;
        return tracer.embree_scene().occluded({receiver, toward, 0, distance}) ? 0.0 : 1.0;
      });
  double e = 0;
  for (const SourceElement& element : elements) {
    const double dz = element.position[2] - receiver[2];
    const double r2 = std::pow(element.position[0] - receiver[0], 2) +
                      std::pow(element.position[1] - receiver[1], 2) + dz * dz;
    e += element.candela * (dz / std::sqrt(r2)) / r2;
  }
  return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tube_sampling)

BOOST_AUTO_TEST_CASE(stratified_shadow_rays_converge_to_the_exact_visible_part_of_the_tube) {
  const auto scene = penumbra::test::scene_from_json("tube", R"({"penumbra": 1,
    "objects": [{"name": "card", "polygon": [[0.25, -1, 1], [3, -1, 1], [3, 1, 1], [0.25, 1, 1]]}],
    "lights": [{"name": "tube", "linear": [[-1, 0, 2], [1, 0, 2]], "candela_per_metre": 100}]})");
  const RayTracer tracer(scene);
  const auto& tube = std::get<penumbra::LinearLight>(scene.lights[0].source);
  const double expected = simpson(-1, 0.5, 20000, integrand);
  // The ray tracer's own value is exact: the closed form over u in [0, 0.75].
  RayCounts counts;
  const double exact = tracer.illuminance({0, 0, 0}, {0, 0, 1}, 1, counts);
  BOOST_TEST(exact == expected, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(exact == penumbra::illuminance::linear_illuminance({0, 0, 0}, {0, 0, 1}, {-1, 0, 2},
                                                                {1, 0, 2}, 100, {{0.0, 0.75}}),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(counts.shadow == 0u);
  // and the exact engine's (illuminance layer) value.
  BOOST_TEST(
      exact == penumbra::illuminance::IlluminanceSolver(scene).light_at(0, {0, 0, 0}, {0, 0, 1}),
      boost::test_tools::tolerance(1e-12));
  // The stratum that holds the shadow edge errs by at most one element, I dl (2/r)^2 / r^2
  // <= 100 * (2 / samples) / 4 lux; the smooth strata err far less. So the error shrinks
  // at least like 1 / samples. Seeds fixed for reproducibility; the bound holds for any.
  for (int samples : {64, 512, 4096}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      int shadow_rays = 0;
      const double e = stratified_estimate(tracer, tube, {0, 0, 0}, samples, seed, shadow_rays);
      BOOST_TEST(shadow_rays == samples);
      BOOST_TEST(std::abs(e - exact) < 1.5 * 100 * (2.0 / samples) / 4);
    }
  }
  // And the unoccluded tube: a receiver beside the card sees all of it.
  const double open_expected = simpson(-1, 1, 20000, [](double x) {
    const double dx = x + 3;  // the element at x seen from (-3, 0, 0)
    const double r2 = dx * dx + 4;
    return 100 * (2 / std::sqrt(r2)) * (2 / std::sqrt(r2)) / r2;
  });
  BOOST_TEST(tracer.illuminance({-3, 0, 0}, {0, 0, 1}, 1, counts) == open_expected,
             boost::test_tools::tolerance(1e-9));
  int shadow_rays = 0;
  const double open = stratified_estimate(tracer, tube, {-3, 0, 0}, 4096, 1, shadow_rays);
  BOOST_TEST(std::abs(open - open_expected) < 1e-3 * open_expected);
}

// Elements over weighted pieces: strata laid end to end over the pieces, each element
// scaled by its piece's factor; with many samples the sum is the weighted closed form.
BOOST_AUTO_TEST_CASE(stratified_elements_over_pieces_carry_their_factor) {
  const penumbra::LinearLight tube{{-1, 0, 2}, {1, 0, 2}, 100};
  const std::vector<TubePiece> pieces{{0.1, 0.3, 1}, {0.5, 0.9, 0.25}};
  const auto elements = sample_tube_stratified(tube, {0, 0, 0}, pieces, 6000, 7);
  BOOST_TEST(elements.size() == 6000u);
  double e = 0;
  for (const SourceElement& element : elements) {
    const double u = (element.position[0] + 1) / 2;
    BOOST_TEST(((u > 0.1 - 1e-12 && u < 0.3 + 1e-12) || (u > 0.5 - 1e-12 && u < 0.9 + 1e-12)));
    const double r2 = element.position[0] * element.position[0] + 4;
    e += element.candela * (2 / std::sqrt(r2)) / r2;
  }
  using penumbra::illuminance::linear_illuminance;
  const double expected =
      linear_illuminance({0, 0, 0}, {0, 0, 1}, {-1, 0, 2}, {1, 0, 2}, 100, {{0.1, 0.3}}) +
      0.25 * linear_illuminance({0, 0, 0}, {0, 0, 1}, {-1, 0, 2}, {1, 0, 2}, 100, {{0.5, 0.9}});
  BOOST_TEST(e == expected, boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_SUITE_END()
