// `--receivers` (shadows, check): the faces of the selected objects, computed alone, are
// exactly the corresponding faces of the full run; the other objects still cast shadows.

#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "support/fixtures.h"

using penumbra::test::run_penumbra;

namespace {

using Faces = std::map<std::string, nlohmann::json>;  // "object/face" -> the face's entry

Faces faces_of(const std::filesystem::path& file) {
  const nlohmann::json document = nlohmann::json::parse(std::ifstream(file));
  Faces faces;
  for (const nlohmann::json& face : document.at("faces"))
    faces[face.at("object").get<std::string>() + "/" + std::to_string(face.at("face").get<int>())] =
        face;
  return faces;
}

// runs shadows on scene in full and with --receivers selection, and checks that the second
// holds exactly the faces of the objects named in expected, each equal to the full run's.
void check_selection(const std::filesystem::path& scene, const std::string& selection,
                     const std::set<std::string>& expected, const std::string& name) {
  const auto dir = penumbra::test::scratch_dir("receivers-run-" + name);
  const auto full = dir / "full.json", part = dir / "part.json";
  const auto all =
      run_penumbra("shadows '" + scene.string() + "' --exact -o '" + full.string() + "'");
  BOOST_TEST_REQUIRE(all.status == 0, all.err);
  const auto some = run_penumbra("shadows '" + scene.string() + "' --exact -o '" + part.string() +
                                 "' --receivers '" + selection + "'");
  BOOST_TEST_REQUIRE(some.status == 0, some.err);

  const Faces everything = faces_of(full), selected = faces_of(part);
  std::size_t wanted = 0;
  for (const auto& [key, face] : everything) {
    if (!expected.count(face.at("object").get<std::string>())) continue;
    ++wanted;
    const auto found = selected.find(key);
    BOOST_TEST_REQUIRE((found != selected.end()), key);
    BOOST_TEST((found->second == face), key);
  }
  BOOST_TEST(selected.size() == wanted);
  BOOST_TEST(wanted > 0u);

  // check --receivers compares those faces with the full golden file.
  const auto checked = run_penumbra("check '" + scene.string() + "' --golden '" + full.string() +
                                    "' --receivers '" + selection + "'");
  BOOST_TEST(checked.status == 0, checked.out + checked.err);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(receivers)

BOOST_AUTO_TEST_CASE(selected_faces_equal_the_full_run_every_kind_of_light) {
  // Point, linear and sun lights; names by list and by pattern (chair/seat and chair/back).
  check_selection(penumbra::test::fixture("scenes/every-kind.json"), "floor,chair*,ball",
                  {"floor", "chair/seat", "chair/back", "ball"}, "every-kind");
}

BOOST_AUTO_TEST_CASE(selected_faces_equal_the_full_run_on_a_generated_city) {
  // 100 rotated buildings (full-double corners) with a street lamp and two tubes.
  const auto dir = penumbra::test::scratch_dir("receivers-city");
  const auto scene = dir / "city.json";
  const std::string command = "python3 '" +
                              (penumbra::test::source_dir() / "scripts/city").string() +
                              "' 100 --lamps > '" + scene.string() + "'";
  BOOST_TEST_REQUIRE(std::system(command.c_str()) == 0);
  std::set<std::string> expected{"ground", "building4"};
  for (int k = 50; k < 60; ++k) expected.insert("building" + std::to_string(k));
  check_selection(scene, "ground,building5?,building4", expected, "city");
}

BOOST_AUTO_TEST_CASE(a_pattern_that_matches_nothing_is_an_input_error) {
  const auto result =
      run_penumbra("shadows fixtures/scenes/every-kind.json --receivers floor,nothing* -o -");
  BOOST_TEST(result.status == 2);
  BOOST_TEST(result.out.empty());
  BOOST_TEST(result.err.find("--receivers") != std::string::npos, result.err);
  BOOST_TEST(result.err.find("nothing*") != std::string::npos, result.err);
}

BOOST_AUTO_TEST_SUITE_END()
