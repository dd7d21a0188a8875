// penumbra raytrace end to end: the image, the values file, the report, the errors.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "support/fixtures.h"

using penumbra::test::run_penumbra;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(raytrace_cli)

BOOST_AUTO_TEST_CASE(writes_the_image_the_values_and_a_ray_report) {
  const auto dir = penumbra::test::scratch_dir("raytrace-cli");
  const auto image = dir / "fig7.png";
  const auto values = dir / "fig7.csv";
  // Whitted's model alone (no indirect light: its radiosity solve differs in the last bits
  // between compilers, docs/raytrace.md)
  const auto result =
      run_penumbra("raytrace fixtures/scenes/whitted-fig7.json -o '" + image.string() +
                   "' --values '" + values.string() + "' --indirect off");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  const std::string png = penumbra::test::read_text(image);
  // The image docs/raytrace.md shows (fixtures/images, looked at when it was made).
  BOOST_TEST(png == penumbra::test::read_text(penumbra::test::fixture("images/whitted-fig7.png")));
  BOOST_REQUIRE(png.size() > 24);
  BOOST_TEST(png.substr(1, 3) == "PNG");
  BOOST_TEST(penumbra::test::png_size(png).first == 160u);
  BOOST_TEST(penumbra::test::png_size(png).second == 120u);
  BOOST_TEST(contains(result.out, "rays "));
  BOOST_TEST(contains(result.out, "refracted "));

  std::istringstream csv(penumbra::test::read_text(values));
  std::string line;
  std::getline(csv, line);
  BOOST_TEST(line == "px,py,object,R,G,B");
  std::size_t rows = 0, glass = 0;
  while (std::getline(csv, line)) {
    ++rows;
    if (contains(line, ",glass_ball,")) ++glass;
  }
  BOOST_TEST(rows == 160u * 120u);
  BOOST_TEST(glass > 100u);  // the glass ball fills a good part of the view
}

BOOST_AUTO_TEST_CASE(a_pixel_centre_sees_rho_e_over_pi) {
  // One pixel looking straight down at a floor lit by a lamp above it: the pixel centre ray
  // hits (0, 0, 0), E = I / h^2 = 100 / 4, L = rho E / pi.
  const auto dir = penumbra::test::scratch_dir("raytrace-pixel");
  std::ofstream(dir / "down.json") << R"({"penumbra": 1,
    "materials": {"paint": {"reflectance": 0.4}},
    "objects": [{"name": "floor", "box": {"min": [-1, -1, -0.1], "max": [1, 1, 0]}, "material": "paint"}],
    "lights": [{"name": "bulb", "point": [0, 0, 2], "candela": 100}],
    "camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 10, "width": 1, "height": 1}})";
  const auto result = run_penumbra("raytrace '" + (dir / "down.json").string() + "' -o '" +
                                   (dir / "down.png").string() + "' --aa none --values '" +
                                   (dir / "down.csv").string() + "'");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  std::istringstream csv(penumbra::test::read_text(dir / "down.csv"));
  std::string header, px, py, object, r;
  std::getline(csv, header);
  std::getline(csv, px, ',');
  std::getline(csv, py, ',');
  std::getline(csv, object, ',');
  std::getline(csv, r, ',');
  BOOST_TEST(object == "floor");
  const double expected = 0.4 * (100.0 / 4) / std::acos(-1.0);
  BOOST_TEST(std::abs(std::stod(r) - expected) < 1e-6 * expected);
}

BOOST_AUTO_TEST_CASE(bad_input_exits_2_and_writes_nothing) {
  const auto dir = penumbra::test::scratch_dir("raytrace-bad");
  const auto image = dir / "x.png";
  // A scene without a camera.
  std::ofstream(dir / "blind.json")
      << R"({"penumbra": 1, "objects": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}]})";
  const auto blind =
      run_penumbra("raytrace '" + (dir / "blind.json").string() + "' -o '" + image.string() + "'");
  BOOST_TEST(blind.status == 2);
  BOOST_TEST(contains(blind.err, "camera"));
  BOOST_TEST(run_penumbra("raytrace fixtures/scenes/whitted-fig7.json -o '" + image.string() +
                          "' --exposure bright")
                 .status == 2);
  BOOST_TEST(run_penumbra("raytrace fixtures/scenes/whitted-fig7.json -o '" + image.string() +
                          "' --aa sometimes")
                 .status == 2);
  BOOST_TEST(!std::filesystem::exists(image));
}

BOOST_AUTO_TEST_SUITE_END()
