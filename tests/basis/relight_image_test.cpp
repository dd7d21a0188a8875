// What `penumbra relight -o image.png` shows, pixel by pixel: a grey-tinted floor under the
// sun alone, where the relit luminance is known in closed form, seen from above.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>

#include "penumbra/base/numbers.h"
#include "support/fixtures.h"

using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

BOOST_AUTO_TEST_SUITE(relight_image)

BOOST_AUTO_TEST_CASE(a_sunlit_floor_shows_rho_e_over_pi_through_the_srgb_curve) {
  // A 4 m x 4 m floor (a two-sided polygon, so nothing interreflects: its two faces are
  // coplanar), reflectance 0.5 tinted (1, 0.5, 0.25), under a vertical sun of 1000 lx: every
  // patch of its top face has E = 1000 lx and luminance L = rho E / pi per channel, so with
  // the exposure k given, every pixel that sees the floor is sRGB(k L) (IEC 61966-2-1), and
  // every other pixel is black.
  const auto dir = scratch_dir("relight-image");
  {
    std::ofstream scene(dir / "floor.json");
    scene << R"({"penumbra": 1,
      "materials": {"tinted": {"reflectance": 0.5, "color": [1, 0.5, 0.25]}},
      "objects": [{"name": "floor", "polygon": [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]],
                   "material": "tinted"}],
      "lights": [{"name": "sun", "directional": [0, 0, -1], "illuminance": 1000}],
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 60,
                 "width": 40, "height": 30}})";
  }
  auto result = run_penumbra("basis " + (dir / "floor.json").string() +
                             " --degree 1 --patch-size 1 -o " + (dir / "floor.pbl").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const double exposure = 0.005;
  result = run_penumbra("relight " + (dir / "floor.pbl").string() + " -o " +
                        (dir / "floor.png").string() + " --exposure 0.005");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const auto image = penumbra::test::read_png(dir / "floor.png");
  BOOST_TEST_REQUIRE((image.width == 40u && image.height == 30u));

  std::array<int, 3> floor_colour{};
  const double tint[3] = {1, 0.5, 0.25};
  for (int c = 0; c < 3; ++c) {
    const double linear = std::min(1.0, exposure * 0.5 * tint[c] * 1000 / penumbra::pi);
    const double encoded =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
    floor_colour[c] = static_cast<int>(std::lround(255 * encoded));
  }
  // The ray through pixel (i, j)'s centre meets z = 0 at eye + 5 (x, y) of the image plane
  // at distance 1, whose half height is tan(30 degrees) (up = +y, right = +x).
  const double half_height = std::tan(penumbra::pi / 6), half_width = half_height * 40 / 30;
  std::size_t floor = 0, outside = 0, wrong = 0;
  for (unsigned j = 0; j < 30; ++j)
    for (unsigned i = 0; i < 40; ++i) {
      const double x = 5 * (2 * (i + 0.5) / 40 - 1) * half_width;
      const double y = 5 * (1 - 2 * (j + 0.5) / 30) * half_height;
      const double margin = std::min(2 - std::abs(x), 2 - std::abs(y));
      if (std::abs(margin) < 0.1) continue;  // a pixel on the floor's edge
      const auto seen = image.at(i, j);
      if (margin > 0) {
        ++floor;
        for (int c = 0; c < 3; ++c) wrong += std::abs(seen[c] - floor_colour[c]) > 1;
      } else {
        ++outside;
        wrong += seen != std::array<int, 3>{0, 0, 0};
      }
    }
  BOOST_TEST(floor >= 350u);  // about 20 x 20 of the 40 x 30 pixels, less the edges
  BOOST_TEST(outside > 100u);
  BOOST_TEST(wrong == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
