#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/raytrace/ray_tracer.h"
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

}  // namespace

BOOST_AUTO_TEST_SUITE(tube_sampling)

BOOST_AUTO_TEST_CASE(stratified_shadow_rays_integrate_the_visible_part_of_the_tube) {
  const auto scene = penumbra::test::scene_from_json("tube", R"({"penumbra": 1,
    "objects": [{"name": "card", "polygon": [[0.25, -1, 1], [3, -1, 1], [3, 1, 1], [0.25, 1, 1]]}],
    "lights": [{"name": "tube", "linear": [[-1, 0, 2], [1, 0, 2]], "candela_per_metre": 100}]})");
  TraceOptions options;
  options.tube_samples = 4096;
  // A fixed seed makes the estimate reproducible; the tolerance below holds for any seed.
  options.seed = 1980;
  const RayTracer tracer(scene, options);
  const double expected = simpson(-1, 0.5, 20000, integrand);
  // The stratum that holds the shadow edge errs by at most one element, I dl (2/r)^2 / r^2
  // <= 100 * (2 / 4096) / 4 = 0.012 lux; the smooth strata err far less.
  for (std::uint64_t key : {1u, 2u, 3u}) {
    RayCounts counts;
    const double e = tracer.illuminance({0, 0, 0}, {0, 0, 1}, key, counts);
    BOOST_TEST(std::abs(e - expected) < 0.02);
    BOOST_TEST(counts.shadow == 4096u);
    // The illuminance layer's closed form over the same visible interval, u in [0, 0.75].
    const double closed_form = penumbra::illuminance::linear_illuminance(
        {0, 0, 0}, {0, 0, 1}, {-1, 0, 2}, {1, 0, 2}, 100, {{0.0, 0.75}});
    BOOST_TEST(std::abs(e - closed_form) < 0.02);
  }
  // And the unoccluded tube: a receiver beside the card sees all of it.
  RayCounts counts;
  const double open = tracer.illuminance({-3, 0, 0}, {0, 0, 1}, 1, counts);
  const double open_expected = simpson(-1, 1, 20000, [](double x) {
    const double dx = x + 3;  // the element at x seen from (-3, 0, 0)
    const double r2 = dx * dx + 4;
    return 100 * (2 / std::sqrt(r2)) * (2 / std::sqrt(r2)) / r2;
  });
  BOOST_TEST(std::abs(open - open_expected) < 1e-3 * open_expected);
  BOOST_TEST(std::abs(open - penumbra::illuminance::linear_illuminance(
                                 {-3, 0, 0}, {0, 0, 1}, {-1, 0, 2}, {1, 0, 2}, 100)) <
             1e-3 * open_expected);
}

BOOST_AUTO_TEST_SUITE_END()
