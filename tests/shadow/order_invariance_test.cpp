// Results must not depend on input order (DESIGN.md, "Exactness"): shuffled
// objects, lights, hull points and rotated polygon cycles, and parallel versus
// serial evaluation, all give the identical exact document.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>

#include "penumbra/io/shadow_json.h"
#include "shadow_support.h"
#include "support/fixtures.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

std::string exact_document(const Scene& scene, const ShadowOptions& options = {}) {
  io::ShadowJsonOptions json_options;
  json_options.exact = true;
  return io::shadow_json(scene, compute_shadows(scene, options), json_options).dump();
}

// returns the scene text with objects, lights and convex points shuffled and polygon
// cycles rotated.
std::string shuffled(const std::string& text, std::mt19937& random) {
  nlohmann::json scene = nlohmann::json::parse(text);
  std::shuffle(scene["objects"].begin(), scene["objects"].end(), random);
  std::shuffle(scene["lights"].begin(), scene["lights"].end(), random);
  for (auto& light : scene["lights"])
    if (light.contains("linear") && random() % 2) std::swap(light["linear"][0], light["linear"][1]);
  for (auto& object : scene["objects"]) {
    if (object.contains("convex"))
      std::shuffle(object["convex"].begin(), object["convex"].end(), random);
    if (object.contains("polygon")) {
      auto& cycle = object["polygon"];
      const auto shift = std::uniform_int_distribution<std::size_t>(0, cycle.size() - 1)(random);
      std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(shift), cycle.end());
    }
  }
  return scene.dump();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(order_invariance)

BOOST_AUTO_TEST_CASE(shuffled_inputs_give_identical_exact_output) {
  std::mt19937 random(42);  // fixed: reproducible shuffles
  for (const char* name : {"every-kind", "shadow-touching", "shadow-cutting", "shadow-shared-face",
                           "shadow-collinear-contour", "shadow-abutting", "linear-fig5",
                           "linear-degenerate", "linear-joint"}) {
    const auto path = fixture(std::string("scenes/") + name + ".json");
    const std::string text = read_text(path);
    const std::string reference = exact_document(parse_scene(text, path));
    for (int round = 0; round < 3; ++round)
      BOOST_TEST(exact_document(parse_scene(shuffled(text, random), path)) == reference, name);
  }
}

BOOST_AUTO_TEST_CASE(parallel_and_serial_evaluation_agree) {
  const Scene scene = load_scene(fixture("scenes/every-kind.json"));
  ShadowOptions serial;
  serial.parallel = false;
  BOOST_TEST(exact_document(scene) == exact_document(scene, serial));
}

BOOST_AUTO_TEST_SUITE_END()
