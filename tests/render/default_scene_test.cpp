// The default scene's pictures (issue #18, item 5; docs/render.md, "The default scene"):
// pixel statistics of what `scripts/demo` renders of fixtures/scenes/default-room.json.

#include <boost/test/unit_test.hpp>

#include <map>
#include <set>
#include <sstream>
#include <string>

#include "support/fixtures.h"

using penumbra::test::fixture;
using penumbra::test::read_text;
using penumbra::test::run_penumbra;
using penumbra::test::scratch_dir;

namespace {

struct Picture {
  penumbra::test::PngImage image;
  std::vector<std::string> object;  // per pixel, "" where nothing is seen
};

// renders the default room at 160 x 120 with options, with its values file.
Picture render(const std::string& name, const std::string& options) {
  const auto dir = scratch_dir("default-scene-" + name);
  const auto result =
      run_penumbra("render " + fixture("scenes/default-room.json").string() + " -o " +
                   (dir / "image.png").string() + " --width 160 --height 120 --values " +
                   (dir / "values.csv").string() + options);
  BOOST_TEST_REQUIRE(result.status == 0, result.err);
  Picture picture{penumbra::test::read_png(dir / "image.png"), std::vector<std::string>(160 * 120)};
  const auto columns = penumbra::test::csv_columns(read_text(dir / "values.csv"));
  const auto& px = columns.at("px");
  for (std::size_t k = 0; k < px.size(); ++k)
    picture.object[std::stoul(columns.at("py")[k]) * 160 + std::stoul(px[k])] =
        columns.at("object")[k];
  return picture;
}

// the number of pixels that see something and are pure black.
std::size_t black_pixels(const Picture& picture) {
  std::size_t black = 0;
  for (unsigned j = 0; j < 120; ++j)
    for (unsigned i = 0; i < 160; ++i)
      if (!picture.object[j * 160 + i].empty() &&
          picture.image.at(i, j) == std::array<int, 3>{0, 0, 0})
        ++black;
  return black;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(default_scene)

BOOST_AUTO_TEST_CASE(no_surface_is_black_where_the_radiosity_solution_has_light) {
  // A closed room lit by three downlights, a tube and the sun through a window: every
  // surface the camera sees gets interreflected light, so no seen pixel is pure black with
  // indirect light; with direct light alone the sides of the sofa and the desk that no lamp
  // sees are black (the picture the issue complained of).
  const Picture lit = render("indirect", "");
  BOOST_TEST(black_pixels(lit) == 0u);
  const Picture direct = render("direct", " --indirect off");
  BOOST_TEST(black_pixels(direct) > 100u);
}

BOOST_AUTO_TEST_CASE(isolux_belts_show_on_the_lit_surfaces) {
  // The belts (every other band between the levels chosen from the picture) are painted on
  // a good share of the picture and on many surfaces, not on one patch.
  const Picture plain = render("plain", "");
  const Picture belts = render("belts", " --isolux");
  std::size_t seen = 0, painted = 0;
  std::set<std::string> objects;
  for (unsigned j = 0; j < 120; ++j)
    for (unsigned i = 0; i < 160; ++i) {
      const std::string& object = plain.object[j * 160 + i];
      if (object.empty() || (i < 40 && j < 60)) continue;  // nothing, or the legend
      ++seen;
      if (belts.image.at(i, j) != plain.image.at(i, j)) {
        ++painted;
        objects.insert(object);
      }
    }
  BOOST_TEST(painted > seen / 5);
  BOOST_TEST(objects.size() >= 5u);
}

BOOST_AUTO_TEST_SUITE_END()
