// penumbra render end to end: the image, the values file, isolux belts, the errors.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "penumbra/base/colour_scale.h"
#include "penumbra/render/isolux_belts.h"
#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {}  // namespace

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
  BOOST_TEST(line == "px,py,object,face,E,L,E_indirect");
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

BOOST_AUTO_TEST_CASE(isolux_belts_paint_exactly_the_odd_bands_in_the_colour_of_their_lux) {
  // What a user sees: the PNG of `render --isolux` against the plain PNG of the same view
  // and the illuminance of every pixel (--values). Nishita 1985 section 5 and docs/render.md:
  // a pixel in an odd band (1 or 3 levels at or below its E) below the last level is painted
  // in the colour of E on a hue scale from blue (240 degrees) at 0 to red (0 degrees) at the
  // maximum max(last level, max E), full saturation; every other pixel is the plain image's,
  // except the legend box in the top-left corner.
  const auto dir = scratch_dir("render-cli-isolux");
  const std::string scene = fixture("scenes/render-interior.json").string();
  const std::string size = " --width 160 --height 120 --exposure 0.02";
  auto result = run_penumbra("render " + scene + " -o " + (dir / "plain.png").string() + size +
                             " --values " + (dir / "values.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  result = run_penumbra("render " + scene + " -o " + (dir / "belts.png").string() + size +
                        " --isolux --levels 20,50,100,200");
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(result.out.find("isolux levels 20 50 100 200 lx") != std::string::npos, result.out);
  const std::vector<double> levels{20, 50, 100, 200};

  const auto plain = penumbra::test::read_png(dir / "plain.png");
  const auto belts = penumbra::test::read_png(dir / "belts.png");
  BOOST_TEST_REQUIRE((plain.width == 160u && plain.height == 120u));
  BOOST_TEST_REQUIRE((belts.width == 160u && belts.height == 120u));
  // px,py,object,face,E,L: the names of this scene hold no comma or quote.
  std::vector<double> illuminance(160 * 120, -1);
  std::istringstream csv(read_text(dir / "values.csv"));
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    std::vector<std::string> field;
    std::istringstream row(line);
    for (std::string item; std::getline(row, item, ',');) field.push_back(item);
    if (field[2].empty()) continue;  // nothing seen
    illuminance[std::stoul(field[1]) * 160 + std::stoul(field[0])] = std::stod(field[4]);
  }
  double maximum = levels.back();
  for (double e : illuminance) maximum = std::max(maximum, e);

  // The hue scale, from HSV with S = V = 1: H = 240 (1 - E / maximum) degrees.
  const auto expected_colour = [&](double e) {
    const double hue = 240 * (1 - std::clamp(e / maximum, 0.0, 1.0)) / 60;
    const double x = 1 - std::abs(std::fmod(hue, 2.0) - 1);
    const double rgb[4][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}};
    const auto& c = rgb[std::min(3, static_cast<int>(hue))];
    return std::array<int, 3>{static_cast<int>(std::lround(255 * c[0])),
                              static_cast<int>(std::lround(255 * c[1])),
                              static_cast<int>(std::lround(255 * c[2]))};
  };
  const auto close = [](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    for (int c = 0; c < 3; ++c)
      if (std::abs(a[c] - b[c]) > 1) return false;  // one step of rounding
    return true;
  };
  // The legend box: one 7-pixel line per level plus a 2-pixel margin, and 6 + 4 x (the
  // longest label, "200 lx" = 6 characters) + 2 pixels wide at this size (scale 1).
  const unsigned legend_width = 6 + 4 * 6 + 2, legend_height = 7 * 4 + 2;
  std::size_t painted[5] = {0, 0, 0, 0, 0}, wrong = 0;
  for (unsigned j = 0; j < 120; ++j)
    for (unsigned i = 0; i < 160; ++i) {
      if (i < legend_width && j < legend_height) continue;
      const double e = illuminance[j * 160 + i];
      const std::size_t band =
          e < 0 ? 0 : std::upper_bound(levels.begin(), levels.end(), e) - levels.begin();
      const bool paint = e >= 0 && band % 2 == 1 && band < levels.size();
      const bool ok =
          paint ? close(belts.at(i, j), expected_colour(e)) : belts.at(i, j) == plain.at(i, j);
      wrong += !ok;
      painted[band] += paint;
    }
  BOOST_TEST(wrong == 0u);
  BOOST_TEST(painted[1] > 0u);  // 20-50 lx
  BOOST_TEST(painted[3] > 0u);  // 100-200 lx
  // The legend's swatches, highest level on top, in the colour of their level.
  for (unsigned k = 0; k < levels.size(); ++k)
    BOOST_TEST(close(belts.at(2, 1 + 7 * k + 2), expected_colour(levels[levels.size() - 1 - k])));
}

BOOST_AUTO_TEST_CASE(every_fixture_renders_to_its_reference_image) {
  // fixtures/images holds the images docs/render.md shows, looked at when they were made:
  // any change to visibility, shadow boundaries, shading or tone mapping shows here. Direct
  // light only, as the paper's Fig. 11: the radiosity solve behind indirect light differs in
  // its last bits between compilers (GCC and clang's sanitizer build), enough to move a byte.
  const auto dir = scratch_dir("render-cli-references");
  for (const char* name :
       {"render-interior", "render-outdoor", "render-room-point", "render-room-linear"})
    for (const bool isolux : {false, true}) {
      const std::string image = std::string(name) + (isolux ? "-isolux" : "") + ".png";
      const auto result = run_penumbra(
          "render " + fixture(std::string("scenes/") + name + ".json").string() + " -o " +
          (dir / image).string() + " --indirect off" + (isolux ? " --isolux" : ""));
      BOOST_TEST_REQUIRE(result.status == 0, result.err);
      BOOST_TEST(read_text(dir / image) == read_text(fixture("images/" + image)), image);
    }
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
  for (const char* options : {" --isolux --false-colour luminance", " --false-colour lux",
                              " --indirect maybe", " --tone bright", " --patch-size 0"})
    BOOST_TEST(run_penumbra("render " + scene + " -o " + image.string() + options).status == 2,
               options);
  BOOST_TEST(!std::filesystem::exists(image));
}

BOOST_AUTO_TEST_CASE(false_colour_paints_every_seen_pixel_in_the_colour_of_its_lux) {
  // docs/render.md, "False colour": with levels spanning more than a factor 20 the scale is
  // logarithmic, hue 240 degrees (blue) at the lowest level to 0 (red) at the largest E
  // seen; every pixel that sees something outside the legend box takes the colour of its E.
  const auto dir = scratch_dir("render-cli-false-colour");
  const std::string scene = fixture("scenes/render-interior.json").string();
  const auto result =
      run_penumbra("render " + scene + " -o " + (dir / "fc.png").string() +
                   " --width 160 --height 120 --false-colour illuminance" +
                   " --levels 1,10,100,1000 --values " + (dir / "values.csv").string());
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  BOOST_TEST(
      result.out.find("false colour illuminance levels 1 10 100 1000 lx") != std::string::npos,
      result.out);
  const auto image = penumbra::test::read_png(dir / "fc.png");
  std::istringstream csv(read_text(dir / "values.csv"));
  std::string line;
  std::getline(csv, line);
  std::vector<std::array<std::string, 5>> rows;
  double top = 1000;
  while (std::getline(csv, line)) {
    std::vector<std::string> field;
    std::istringstream row(line);
    for (std::string item; std::getline(row, item, ',');) field.push_back(item);
    rows.push_back({field[0], field[1], field[2], field[4], ""});
    if (!field[2].empty()) top = std::max(top, std::stod(field[4]));
  }
  std::size_t checked = 0;
  for (const auto& row : rows) {
    const unsigned i = std::stoul(row[0]), j = std::stoul(row[1]);
    if (row[2].empty() || j < 40) continue;  // nothing seen, or the legend's rows
    const double e = std::stod(row[3]);
    const double fraction = e > 1 ? std::log(e) / std::log(top) : 0;
    const penumbra::Rgb8 expected = penumbra::scale_colour(fraction);
    const std::size_t at = 3 * (j * 160 + i);
    for (int c = 0; c < 3; ++c)
      BOOST_TEST(std::abs(int(image.rgb[at + c]) - int(expected[c])) <= 2,
                 "pixel " << i << ", " << j << " E " << e);
    ++checked;
  }
  BOOST_TEST(checked > 5000u);
}

BOOST_AUTO_TEST_CASE(belt_colours_run_from_blue_to_red) {
  using penumbra::render::belt_colour;
  BOOST_TEST((belt_colour(0, 100) == penumbra::Rgb8{0, 0, 255}));
  BOOST_TEST((belt_colour(100, 100) == penumbra::Rgb8{255, 0, 0}));
  BOOST_TEST((belt_colour(50, 100) == penumbra::Rgb8{0, 255, 0}));
  BOOST_TEST(penumbra::render::isolux_band(5, {10, 20}) == 0);
  BOOST_TEST(penumbra::render::isolux_band(10, {10, 20}) == 1);
  BOOST_TEST(penumbra::render::isolux_band(25, {10, 20}) == 2);
}

BOOST_AUTO_TEST_SUITE_END()
