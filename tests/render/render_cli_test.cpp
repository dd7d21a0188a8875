// penumbra render end to end: the image, the values file, isolux belts, the errors.

#include <boost/test/unit_test.hpp>

#include <sstream>

#include "penumbra/render/isolux_belts.h"
#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {

}  // namespace

BOOST_AUTO_TEST_SUITE(render_cli)

BOOST_AUTO_TEST_CASE(writes_the_image_and_one_row_per_pixel) {
  const auto dir = scratch_dir("render-cli");
  const auto result =
      run_penumbra("render " + fixture("scenes/render-shadow-edge.json").string() + " -o " +
                   (dir / "edge.png").string() + " --width 40 --height 30 --values " +
                   (dir / "edge.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST((penumbra::test::png_size(read_text(dir / "edge.png")) == std::make_pair(40u, 30u)));
  std::istringstream csv(read_text(dir / "edge.csv"));
  std::string line;
  std::getline(csv, line);
  BOOST_TEST(line == "px,py,object,face,E,L");
  std::size_t rows = 0, floor = 0, nothing = 0;
  while (std::getline(csv, line)) {
    ++rows;
    if (line.find(",floor,") != std::string::npos) ++floor;
    if (line.find(",,,") != std::string::npos) ++nothing;
  }
  BOOST_TEST(rows == 40u * 30u);
  BOOST_TEST(floor > 0u);
  // at 40 x 30 with a 90 degree vertical view from 10 m, the view spans |X| < 13.3 m but
  // the floor only |X| <= 4 m: the columns beyond see nothing
  BOOST_TEST(nothing > 0u);
  BOOST_TEST(floor + nothing < rows);  // the plate is seen too
}

BOOST_AUTO_TEST_CASE(isolux_paints_belts_and_reports_levels) {
  const auto dir = scratch_dir("render-cli-isolux");
  const auto result = run_penumbra("render " + fixture("scenes/render-interior.json").string() +
                                   " -o " + (dir / "belts.png").string() +
                                   " --width 80 --height 60 --isolux --levels 20,50,100,200");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(result.out.find("isolux levels 20 50 100 200 lx") != std::string::npos, result.out);
}

BOOST_AUTO_TEST_CASE(bad_input_exits_2_and_writes_nothing) {
  const auto dir = scratch_dir("render-cli-bad");
  const auto image = dir / "never.png";
  const std::string scene = fixture("scenes/render-interior.json").string();
  BOOST_TEST(run_penumbra("render " + scene + " -o " + image.string() + " --levels 10,x").status ==
             2);
  BOOST_TEST(run_penumbra("render " + scene + " -o " + image.string() + " --interval 0").status ==
             2);
  BOOST_TEST(run_penumbra("render " + fixture("scenes/shadow-cube-sun.json").string() + " -o " +
                          image.string())
                 .status == 2);  // no camera
  BOOST_TEST(!std::filesystem::exists(image));
}

BOOST_AUTO_TEST_CASE(belt_colours_run_from_blue_to_red) {
  using penumbra::render::belt_colour;
  BOOST_TEST((belt_colour(0, 100) == penumbra::render::Rgb8{0, 0, 255}));
  BOOST_TEST((belt_colour(100, 100) == penumbra::render::Rgb8{255, 0, 0}));
  BOOST_TEST((belt_colour(50, 100) == penumbra::render::Rgb8{0, 255, 0}));
  BOOST_TEST(penumbra::render::isolux_band(5, {10, 20}) == 0);
  BOOST_TEST(penumbra::render::isolux_band(10, {10, 20}) == 1);
  BOOST_TEST(penumbra::render::isolux_band(25, {10, 20}) == 2);
}

BOOST_AUTO_TEST_SUITE_END()
