// Objects of Bézier patches in scene files (issue #23, docs/bezier-patches.md): the patch
// file, the inline form, placement, the tessellation the exact verbs see, and the errors.

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <set>

#include "penumbra/base/input_error.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

using namespace penumbra;

namespace {

// parses scene text as a file in dir (so that relative patch files resolve there).
Scene parse_in(const std::filesystem::path& dir, const std::string& text) {
  return parse_scene(text, dir / "scene.json");
}

std::string patch_file_scene(const std::string& file) {
  return R"({"penumbra": 1, "objects": [{"name": "pot", "bezier_patches": ")" + file + R"("}]})";
}

// a patch file with the given text in a scratch directory; returns the directory.
std::filesystem::path with_patch_file(const std::string& name, const std::string& text) {
  const auto dir = test::scratch_dir("bezier-" + name);
  std::ofstream(dir / "p.bpt") << text;
  return dir;
}

// the text of one flat patch over [0, 3] x [0, 3] at height z (points (i, j, z)).
std::string flat_patch_text(double z) {
  std::string text = "3 3\n";
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      text += std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(z) + "\n";
  return text;
}

void expect_error(const std::filesystem::path& dir, const std::string& text,
                  const std::string& location, const std::string& fragment) {
  try {
    parse_in(dir, text);
    BOOST_ERROR("no error for " << fragment);
  } catch (const InputError& e) {
    BOOST_TEST(e.location().rfind(location, 0) == 0, "location \"" << e.location() << "\"");
    BOOST_TEST(std::string(e.what()).find(fragment) != std::string::npos, "message: " << e.what());
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bezier_objects)

BOOST_AUTO_TEST_CASE(the_teapot_file_loads_as_patches_and_their_tessellation) {
  const Scene scene = load_scene(test::fixture("scenes/bezier-teapot.json"));
  std::set<const void*> patch_sets;
  std::size_t pieces = 0;
  for (const Object& object : scene.objects)
    if (object.patches) {
      patch_sets.insert(object.patches.get());
      ++pieces;
      BOOST_TEST(object.part == "teapot");
      BOOST_TEST(object.kind == "bezier");
    }
  BOOST_TEST_REQUIRE(patch_sets.size() == 1u);
  const auto& patches = *scene.objects[scene.find_object("teapot#0") - &scene.objects[0]].patches;
  BOOST_TEST(patches.size() == 32u);  // Newell's teapot with Crow's bottom
  // Placed: scale 0.5, then moved 1.5 along y. The first control point of the rim is
  // (1.4, 0, 2.4) in the file.
  BOOST_TEST(patches[0].points[0][0] == 0.7);
  BOOST_TEST(patches[0].points[0][1] == 1.5);
  BOOST_TEST(patches[0].points[0][2] == 1.2);
  BOOST_TEST_REQUIRE(scene.tessellated.size() == 1u);
  const TessellatedPatches& record = scene.tessellated[0];
  BOOST_TEST(record.name == "teapot");
  BOOST_TEST(record.patches == 32u);
  BOOST_TEST(record.tolerance == 0.01);
  // n x n cells of two triangles per patch; the triangles at the collapsed rows of the lid's
  // and the bottom's patches (8 patches whose row u = 0 is one point) are degenerate: one per
  // cell of that row.
  std::size_t n = 1;
  while (32 * 2 * n * n - 8 * n < record.triangles) ++n;
  BOOST_TEST(32 * 2 * n * n - 8 * n == record.triangles);
  BOOST_TEST(pieces >= record.triangles / 2);
  bool noted = false;
  for (const std::string& warning : scene.warnings)
    noted = noted ||
            warning.find("32 Bézier patches tessellated into " + std::to_string(record.triangles) +
                         " triangles within 0.01 m") != std::string::npos;
  BOOST_TEST(noted);
}

BOOST_AUTO_TEST_CASE(inline_patches_one_or_a_list) {
  const auto dir = test::scratch_dir("bezier-inline");
  std::string points;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      points +=
          std::string(i + j ? "," : "") + "[" + std::to_string(i) + "," + std::to_string(j) + ",0]";
  const Scene one =
      parse_in(dir, R"({"penumbra": 1, "objects": [{"name": "a", "bezier": [)" + points + "]}]}");
  BOOST_TEST(one.tessellated.at(0).patches == 1u);
  // A flat patch: its two triangles lie in one plane and merge into one convex face.
  BOOST_TEST(one.tessellated.at(0).triangles == 2u);
  BOOST_TEST(one.objects.size() == 1u);
  BOOST_TEST(one.objects[0].solid.faces()[0].vertices.size() == 4u);
  const Scene two = parse_in(dir, R"({"penumbra": 1, "objects": [{"name": "a", "bezier": [[)" +
                                      points + "],[" + points + "]]}]}");
  BOOST_TEST(two.tessellated.at(0).patches == 2u);
}

BOOST_AUTO_TEST_CASE(bad_patches_are_named_by_file_and_line_or_path) {
  const auto dir = test::scratch_dir("bezier-bad");
  expect_error(dir, patch_file_scene("none.bpt"), "objects[0].bezier_patches",
               "cannot open the patch file");
  expect_error(with_patch_file("degrees", "1\n3 2\n"), patch_file_scene("p.bpt"),
               "objects[0].bezier_patches", "line 2: only bicubic patches");
  expect_error(with_patch_file("short", "1\n" + flat_patch_text(0).substr(0, 40)),
               patch_file_scene("p.bpt"), "objects[0].bezier_patches", "the file ends where");
  expect_error(with_patch_file("nan", "1\n3 3\n0 0 nan\n"), patch_file_scene("p.bpt"),
               "objects[0].bezier_patches", "line 3: \"nan\" is not a finite number");
  expect_error(with_patch_file("arity", "1\n3 3\n0 0\n"), patch_file_scene("p.bpt"),
               "objects[0].bezier_patches", "line 3: expected a control point x y z, found 2");
  expect_error(with_patch_file("count", "0\n"), patch_file_scene("p.bpt"),
               "objects[0].bezier_patches", "the number of patches must be a positive integer");
  expect_error(with_patch_file("extra", "1\n" + flat_patch_text(0) + "7\n"),
               patch_file_scene("p.bpt"), "objects[0].bezier_patches",
               "unexpected content after the last patch");
  expect_error(dir, R"({"penumbra": 1, "objects": [{"bezier": [[0,0,0],[1,0,0],[2,0,0]]}]})",
               "objects[0].bezier", "expected at least 16 points, found 3");
  std::string seventeen;
  for (int k = 0; k < 17; ++k)
    seventeen += std::string(k ? "," : "") + "[" + std::to_string(k) + ",0,0]";
  expect_error(dir, R"({"penumbra": 1, "objects": [{"bezier": [)" + seventeen + "]}]}",
               "objects[0].bezier", "a bicubic patch has 16 control points");
  expect_error(dir, R"({"penumbra": 1, "objects": [{"bezier": []}]})", "objects[0].bezier",
               "must not be empty");
  expect_error(with_patch_file("good", "1\n" + flat_patch_text(0)),
               R"({"penumbra": 1, "objects": [{"bezier_patches": "p.bpt", "tolerance": 0}]})",
               "objects[0].tolerance", "");
  // A tolerance so fine that the tessellation would be enormous is refused before it is made.
  expect_error(dir,
               R"({"penumbra": 1, "objects": [{"bezier_patches": ")" +
                   test::fixture("meshes/teapot.bpt").string() + R"(", "tolerance": 1e-7}]})",
               "objects[0].tolerance",
               "within 1e-07 m would have 67108864 triangles, more than the limit of 2000000");
  expect_error(dir,
               R"({"penumbra": 1, "objects": [{"bezier_patches": ")" +
                   test::fixture("meshes/teapot.bpt").string() + R"(", "scale": 1e300,
                   "transform": [1e300,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})",
               "objects[0].bezier_patches", "a control point is not finite once placed");
  // Every patch collapsed to a point: nothing to tessellate.
  std::string point;
  for (int k = 0; k < 16; ++k) point += std::string(k ? "," : "") + "[1,1,1]";
  expect_error(dir, R"({"penumbra": 1, "objects": [{"bezier": [)" + point + "]}]}",
               "objects[0].bezier", "every patch is degenerate");
}

BOOST_AUTO_TEST_SUITE_END()
