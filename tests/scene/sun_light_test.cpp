// A sun given by place and time (docs/sun.md, DESIGN.md "lights"): the direction the loader
// gives it against the NREL SPA report's worked example, north_deg, a sun below the
// horizon, and the errors.

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "penumbra/scene/load_scene.h"

using namespace penumbra;

namespace {

// The worked example of Reda and Andreas, "Solar Position Algorithm for Solar Radiation
// Applications", NREL/TP-560-34302 (2004, rev. 2008), appendix A.5: Golden, Colorado,
// 2003-10-17 12:30:30 local time at UTC-7, elevation 1830.14 m, 820 mbar, 11 degrees C;
// published topocentric zenith 50.11162 degrees (refracted), azimuth 194.34024 degrees.
std::string spa_example_scene(double north_deg, const std::string& time) {
  return R"({"penumbra": 1, "north_deg": )" + std::to_string(north_deg) + R"(,
    "lights": [{"name": "sun", "sun": {"latitude": 39.742476, "longitude": -105.1786,
      "elevation": 1830.14, "pressure": 820, "temperature": 11, "time": ")" +
         time + R"("}, "illuminance": 100000}]})";
}

// the direction sunlight travels for a sun at azimuth A (from true north through east) and
// elevation e, with true north at angle n counter-clockwise from the model's +Y (derived
// here: north = (-sin n, cos n, 0), east = north turned clockwise = (cos n, sin n, 0)).
Vec3d expected_direction(double azimuth_deg, double elevation_deg, double north_deg) {
  const double a = azimuth_deg * pi / 180, e = elevation_deg * pi / 180, n = north_deg * pi / 180;
  const Vec3d north{-std::sin(n), std::cos(n), 0}, east{std::cos(n), std::sin(n), 0};
  Vec3d toward;
  for (int i = 0; i < 3; ++i)
    toward[i] = std::cos(e) * (std::cos(a) * north[i] + std::sin(a) * east[i]);
  toward[2] += std::sin(e);
  return {-toward[0], -toward[1], -toward[2]};
}

double angle_deg(const Vec3d& a, const Vec3d& b) {
  double dot = 0, aa = 0, bb = 0;
  for (int i = 0; i < 3; ++i) {
    dot += a[i] * b[i];
    aa += a[i] * a[i];
    bb += b[i] * b[i];
  }
  return std::acos(std::min(1.0, dot / std::sqrt(aa * bb))) * 180 / pi;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sun_light)

BOOST_AUTO_TEST_CASE(direction_matches_the_spa_worked_example_for_any_north) {
  for (double north : {0.0, 30.0, 90.0, -135.0}) {
    const Scene scene =
        parse_scene(spa_example_scene(north, "2003-10-17T12:30:30-07:00"), "s.json");
    BOOST_TEST_REQUIRE(scene.lights.size() == 1u);
    BOOST_TEST(scene.north_deg == north);
    const auto& sun = std::get<DirectionalLight>(scene.lights[0].source);
    BOOST_TEST(sun.illuminance == 100000);
    const Vec3d expected = expected_direction(194.34024, 90 - 50.11162, north);
    // docs/sun.md: within 0.01 degrees of the published position.
    BOOST_TEST(angle_deg(sun.direction, expected) < 0.01, "north " << north);
    BOOST_TEST_REQUIRE(scene.suns.size() == 1u);
    BOOST_TEST(scene.suns[0].time.offset_minutes == -7 * 60);
    BOOST_TEST(scene.suns[0].atmosphere.has_value());
  }
}

BOOST_AUTO_TEST_CASE(a_sun_below_the_horizon_lights_nothing_and_says_so) {
  // 02:00 local in Golden in October: the sun is far below the horizon.
  const Scene scene = parse_scene(spa_example_scene(0, "2003-10-17T02:00:00-07:00"), "s.json");
  BOOST_TEST(scene.lights.empty());
  BOOST_TEST(scene.suns.size() == 1u);  // kept for sun studies
  BOOST_TEST_REQUIRE(scene.warnings.size() == 1u);
  BOOST_TEST(scene.warnings[0].find("below the horizon") != std::string::npos);
  BOOST_TEST(scene.warnings[0].find("lights[0]") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_sun_fields_name_the_path) {
  const auto message = [](const std::string& sun) {
    try {
      parse_scene(R"({"penumbra": 1, "lights": [{"sun": )" + sun + R"(, "illuminance": 1}]})",
                  "bad.json");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  BOOST_TEST(message(R"({"latitude": 91, "longitude": 0, "time": "2026-03-21T12:00Z"})")
                 .find("lights[0].sun.latitude") != std::string::npos);
  BOOST_TEST(message(R"({"latitude": 0, "longitude": 0, "time": "2026-13-21T12:00Z"})")
                 .find("lights[0].sun.time") != std::string::npos);
  BOOST_TEST(
      message(R"({"latitude": 0, "longitude": 0, "time": "2026-03-21T12:00"})").find("offset") !=
      std::string::npos);
  BOOST_TEST(message(R"({"latitude": 0, "longitude": 0, "time": "2026-03-21T12:00Z",
                         "pressure": 1000})")
                 .find("temperature") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
