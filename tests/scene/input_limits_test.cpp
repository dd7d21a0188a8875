// The limits on what penumbra reads (docs/reliability.md, "Limits"): files that are not
// regular files or are over their kind's size, JSON nested too deep, spheres too fine,
// images too large, a patch size that would make too many patches. Each is refused with an
// InputError naming the file (exit status 2 on the command line, no output written) before
// anything large is allocated. Oversized files are sparse: making one costs no disk.

#include <boost/test/unit_test.hpp>
#include <fstream>

#include "penumbra/base/input_error.h"
#include "penumbra/base/input_file.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/scene/camera.h"
#include "penumbra/scene/load_scene.h"
#include "support/fixtures.h"

namespace penumbra {
namespace {

// returns the message of the InputError action throws (fails the test if it throws none).
template <typename Action>
std::string refusal(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  BOOST_ERROR("no InputError");
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// a sparse file of size bytes.
std::filesystem::path sparse_file(const std::filesystem::path& path, std::uintmax_t size) {
  std::ofstream(path).put('{');
  std::filesystem::resize_file(path, size);
  return path;
}

// n arrays, each inside the next.
std::string nested(int n) {
  return std::string(static_cast<std::size_t>(n), '[') +
         std::string(static_cast<std::size_t>(n), ']');
}

std::string scene_with(const std::string& objects, const std::string& extra = "") {
  return R"({"penumbra": 1, "objects": [)" + objects +
         R"(], "lights": [{"name": "l", "point": [0, 0, 9], "candela": 1}])" + extra + "}";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(input_limits)

BOOST_AUTO_TEST_CASE(a_device_a_directory_and_a_missing_file_are_refused_by_name) {
  const auto dir = test::scratch_dir("limits-kinds");
  // /dev/zero never ends: reading it would exhaust memory
  const std::string device = refusal([] { load_scene("/dev/zero"); });
  BOOST_TEST(contains(device, "/dev/zero: cannot open the scene file: it is not a regular file"),
             device);
  BOOST_TEST(contains(refusal([&] { load_scene(dir); }), "it is a directory"));
  BOOST_TEST(contains(refusal([&] { load_scene(dir / "none.json"); }), "it does not exist"));
  // the same for a photometric file and a model named by a scene
  const std::string ies = refusal([&] {
    parse_scene(R"({"penumbra": 1, "objects": [], "lights": [{"name": "l", "point": [0, 0, 3],
                   "lid": {"ies": "/dev/zero"}}]})",
                dir / "s.json");
  });
  BOOST_TEST(contains(ies, "/dev/zero: cannot open the photometric file: it is not a regular file"),
             ies);
  const std::string model = refusal(
      [&] { parse_scene(scene_with(R"({"name": "m", "mesh": "/dev/zero"})"), dir / "s.json"); });
  BOOST_TEST(contains(model, "cannot open the model file: it is not a regular file"), model);
}

BOOST_AUTO_TEST_CASE(files_over_their_limit_are_refused_before_reading) {
  const auto dir = test::scratch_dir("limits-size");
  const auto scene = sparse_file(dir / "big.json", file_limits::scene + 1);
  const std::string message = refusal([&] { load_scene(scene); });
  BOOST_TEST(
      contains(message, "the scene file is " + std::to_string(file_limits::scene + 1) +
                            " bytes, over the limit of " + std::to_string(file_limits::scene)),
      message);
  const auto lamp = sparse_file(dir / "big.ies", file_limits::photometric + 1);
  BOOST_TEST(contains(refusal([&] {
                        parse_scene(R"({"penumbra": 1, "objects": [], "lights": [{"name": "l",
                                       "point": [0, 0, 3], "lid": {"ies": "big.ies"}}]})",
                                    dir / "s.json");
                      }),
                      "the photometric file is"));
  // at the limit it is read (and then refused for what it holds, not for its size)
  const auto at_limit = sparse_file(dir / "edge.ies", file_limits::photometric);
  const std::string read = refusal([&] {
    parse_scene(R"({"penumbra": 1, "objects": [], "lights": [{"name": "l",
                   "point": [0, 0, 3], "lid": {"ies": "edge.ies"}}]})",
                dir / "s.json");
  });
  BOOST_TEST(!contains(read, "over the limit"), read);
}

BOOST_AUTO_TEST_CASE(json_nested_deeper_than_the_limit_is_refused) {
  // depth = arrays open around the innermost value: nested(n) reaches depth n
  BOOST_CHECK_NO_THROW(parse_input_json(nested(max_json_depth), "f.json"));
  const std::string deeper =
      refusal([] { parse_input_json(nested(max_json_depth + 1), "f.json"); });
  BOOST_TEST(contains(deeper, "nested more than 64 deep"), deeper);
  // a million deep in a scene: refused, not a stack overflow
  const std::string scene = refusal(
      [] { parse_scene(R"({"penumbra": 1, "objects": )" + nested(1000000) + "}", "deep.json"); });
  // where: the 65th container, the 64th "[" after the scene's "{", opens at column 28 + 63
  // (the first "[" follows the 27 characters of '{"penumbra": 1, "objects": ')
  BOOST_TEST(contains(scene, "deep.json: line 1, column 91: arrays and objects nested more than"),
             scene);
  // brackets in strings, escaped quotes among them, are not nesting
  const std::string in_string = "{\"a\": \"\\\"" + std::string(100, '[') + "\"}";
  BOOST_CHECK_NO_THROW(parse_input_json(in_string, "s.json"));
  BOOST_TEST(parse_input_json(in_string, "s.json")["a"].get<std::string>().size() == 101u);
  // a syntax error still gives its line and column
  BOOST_TEST(contains(refusal([] { parse_input_json("{\n  \"a\": [1,, 2]\n}", "g.json"); }),
                      "g.json: line 2, column 11: malformed JSON"));
}

BOOST_AUTO_TEST_CASE(spheres_and_cameras_over_their_limits_are_refused) {
  const std::string sphere = refusal([] {
    parse_scene(scene_with(R"({"name": "s", "sphere": {"center": [0, 0, 0], "radius": 1,
                              "segments": 513}})"),
                "s.json");
  });
  BOOST_TEST(contains(sphere, "objects[0].sphere.segments: a sphere has at most 512 segments"),
             sphere);
  const auto camera = [](int width, int height) {
    return scene_with("", R"(, "camera": {"eye": [0, -5, 1], "target": [0, 0, 0], "width": )" +
                              std::to_string(width) + R"(, "height": )" + std::to_string(height) +
                              "}");
  };
  BOOST_CHECK_NO_THROW(parse_scene(camera(8192, 8192), "c.json"));
  BOOST_CHECK_NO_THROW(parse_scene(camera(16384, 4096), "c.json"));
  BOOST_TEST(contains(refusal([&] { parse_scene(camera(16385, 10), "c.json"); }),
                      "camera: an image side is at most 16384 pixels"));
  // 8192 x 8193 = 2^26 + 8192 pixels
  BOOST_TEST(contains(refusal([&] { parse_scene(camera(8192, 8193), "c.json"); }),
                      "an image has at most 67108864 pixels (8192 x 8193 asked)"));
  BOOST_TEST(image_size_problem(1, 1).empty());
  BOOST_TEST(!image_size_problem(0, 1).empty());
}

BOOST_AUTO_TEST_CASE(a_patch_size_making_too_many_patches_is_refused_before_meshing) {
  // a 100 m cube at 1 cm patches: 10^4 x 10^4 cells on its first face, over 500,000
  const Scene scene = parse_scene(
      scene_with(R"({"name": "b", "box": {"min": [0, 0, 0], "max": [100, 100, 100]}})"), "b.json");
  const std::string message = refusal([&] { basis::PatchMesh::subdivide(scene, 0.01); });
  BOOST_TEST(contains(message, "--patch-size: a patch size of 0.010000 m makes more than 500000"),
             message);
  // at 15 cm: 667^2 = 444,889 cells on one face, refused by the sum over the six faces
  BOOST_TEST(!refusal([&] { basis::PatchMesh::subdivide(scene, 0.15); }).empty());
  // at 25 cm: 400^2 x 6 = 960,000 > 500,000 as well; at 50 cm: 200^2 x 6 = 240,000 patches
  BOOST_TEST(basis::PatchMesh::subdivide(scene, 0.5).size() == 240000u);
}

BOOST_AUTO_TEST_CASE(the_command_line_exits_2_and_writes_nothing) {
  const auto dir = test::scratch_dir("limits-cli");
  const auto out = dir / "out.json";
  const test::CommandResult device =
      test::run_penumbra("shadows /dev/zero -o '" + out.string() + "'");
  BOOST_TEST(device.status == 2);
  BOOST_TEST(
      contains(device.err, "/dev/zero: cannot open the scene file: it is not a regular file"),
      device.err);
  BOOST_TEST(!std::filesystem::exists(out));
  const test::CommandResult wide =
      test::run_penumbra("render '" + test::fixture("scenes/render-room-point.json").string() +
                         "' --width 16384 --height 16384 -o '" + (dir / "big.png").string() + "'");
  BOOST_TEST(wide.status == 2);
  BOOST_TEST(contains(wide.err, "an image has at most 67108864 pixels"), wide.err);
  BOOST_TEST(!std::filesystem::exists(dir / "big.png"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace penumbra
