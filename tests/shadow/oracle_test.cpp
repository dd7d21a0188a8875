// The shadow engine against an exact oracle written independently of it
// (tests/shadow/oracle.h): at random rational points of every face, "in shadow"
// must equal "the open segment to the light meets an occluder's interior", on
// random scenes built on a coarse grid (so that touching, coplanar and grazing
// configurations are frequent) and on the degenerate fixtures.

#include <boost/test/unit_test.hpp>

#include <random>
#include <sstream>

#include "oracle.h"
#include "shadow_support.h"
#include "support/fixtures.h"
#include "support/heavy.h"

using namespace penumbra;
using namespace penumbra::test;

namespace {

struct Tally {
  std::size_t compared = 0;
  std::size_t on_boundary = 0;
  std::size_t disagreements = 0;
};

// compares the engine with the oracle at samples random points of every face.
void compare(const Scene& scene, const ShadowResult& result, int samples, std::mt19937& random,
             Tally& tally, const std::string& label) {
  for (const LightShadows& light : result.lights) {
    const Light& source = scene.lights[light.light];
    for (std::size_t r = 0; r < result.receivers.size(); ++r) {
      const Object& object = scene.objects[result.receivers[r].object];
      const Face& face = object.solid.faces()[result.receivers[r].face];
      const FaceShadow& shadow = light.faces[r];
      if (shadow.beyond_range) continue;
      const Ring2 ring = face_ring(face);
      for (int s = 0; s < samples; ++s) {
        const Point2 p = random_point(ring, random);
        const Where in_shadow = locate(shadow.shadow, p);
        const Where in_lit = locate(shadow.lit, p);
        // On the boundary of one occluder's closed shadow polygon the open definition
        // and the regularized union may differ (e.g. the lit line between two shadows
        // that abut, which regularization fills): such points are counted apart.
        bool on_an_edge = in_shadow == Where::boundary || in_lit == Where::boundary;
        for (const OccluderShadow& occluder : shadow.occluders)
          on_an_edge = on_an_edge || locate(convex_region(occluder.polygon), p) == Where::boundary;
        if (on_an_edge) {
          ++tally.on_boundary;
          continue;
        }
        ++tally.compared;
        // Shadow and lit partition the face.
        BOOST_TEST(((in_shadow == Where::inside) != (in_lit == Where::inside)));
        const bool oracle = oracle_in_shadow(scene, face, face.frame.to_world(p), source);
        if (oracle != (in_shadow == Where::inside)) {
          ++tally.disagreements;
          if (tally.disagreements <= 5)
            BOOST_ERROR(label << ": light " << source.name << ", " << object.name << " face "
                              << result.receivers[r].face << ", point "
                              << to_double(face.frame.to_world(p))[0] << ", "
                              << to_double(face.frame.to_world(p))[1] << ", "
                              << to_double(face.frame.to_world(p))[2] << ": oracle says "
                              << (oracle ? "shadow" : "lit"));
        }
      }
    }
  }
}

// a coordinate on a grid of step 1/2 in [0, 4]
std::string grid(std::mt19937& random) {
  return std::to_string(std::uniform_int_distribution<int>(0, 8)(random) / 2.0);
}

std::string grid_point(std::mt19937& random) {
  return "[" + grid(random) + ", " + grid(random) + ", " + grid(random) + "]";
}

// builds a random scene: boxes, hulls of random grid points and triangles, with a
// point light and a sun whose direction has small integer components (so that it
// is often parallel to faces).
std::string random_scene(std::mt19937& random) {
  std::ostringstream text;
  text << "{\"penumbra\": 1, \"objects\": [";
  const int count = std::uniform_int_distribution<int>(4, 8)(random);
  for (int k = 0; k < count; ++k) {
    text << (k ? "," : "") << "{\"name\": \"o" << k << "\", ";
    const int kind = std::uniform_int_distribution<int>(0, 2)(random);
    if (kind == 0) {
      std::uniform_int_distribution<int> cell(0, 6), size(1, 3);
      const int x = cell(random), y = cell(random), z = cell(random);
      text << "\"box\": {\"min\": [" << x / 2.0 << ", " << y / 2.0 << ", " << z / 2.0
           << "], \"max\": [" << (x + size(random)) / 2.0 << ", " << (y + size(random)) / 2.0
           << ", " << (z + size(random)) / 2.0 << "]}}";
    } else if (kind == 1) {
      text << "\"convex\": [";
      for (int p = 0; p < 7; ++p) text << (p ? ", " : "") << grid_point(random);
      text << "]}";
    } else {
      text << "\"polygon\": [" << grid_point(random) << ", " << grid_point(random) << ", "
           << grid_point(random) << "]}";
    }
  }
  std::uniform_int_distribution<int> component(-2, 2);
  int dx = 0, dy = 0, dz = 0;
  while (dx == 0 && dy == 0 && dz == 0)
    dx = component(random), dy = component(random), dz = component(random);
  text << "], \"lights\": [{\"name\": \"bulb\", \"point\": " << grid_point(random)
       << ", \"candela\": 100}, {\"name\": \"sun\", \"directional\": [" << dx << ", " << dy << ", "
       << dz << "], \"illuminance\": 1000}]}";
  return text.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(shadow_oracle)

BOOST_AUTO_TEST_CASE(random_grid_scenes_agree_with_the_exact_oracle) {
  // Fixed seed: the scenes must be the same on every run so a failure can be replayed.
  std::mt19937 random(20240603);
  Tally tally;
  int scenes = 0;
  while (scenes < penumbra::test::samples(40)) {
    Scene scene;
    try {
      scene = scene_from_text(random_scene(random));
    } catch (const std::exception&) {
      continue;  // e.g. a hull of coplanar points or a collinear triangle: draw again
    }
    ++scenes;
    ShadowOptions options;
    options.range_fraction = 0;
    compare(scene, compute_shadows(scene, options), 12, random, tally,
            "scene " + std::to_string(scenes));
  }
  BOOST_TEST_MESSAGE("oracle, random scenes: " << tally.compared << " points compared, "
                                               << tally.on_boundary << " on a boundary, "
                                               << tally.disagreements << " disagreements");
  BOOST_TEST(tally.compared >= std::size_t(penumbra::test::samples(5000)));
  BOOST_TEST(tally.disagreements == 0u);
}

BOOST_AUTO_TEST_CASE(degenerate_fixtures_agree_with_the_exact_oracle) {
  std::mt19937 random(7);  // fixed: reproducible sample points
  Tally tally;
  for (const char* name :
       {"shadow-cube-point", "shadow-cube-sun", "shadow-touching", "shadow-cutting",
        "shadow-behind-light", "shadow-shared-face", "shadow-light-in-plane", "shadow-sun-parallel",
        "shadow-abutting", "shadow-collinear-contour", "shadow-light-inside"}) {
    const Scene scene = load_scene(fixture(std::string("scenes/") + name + ".json"));
    ShadowOptions options;
    options.range_fraction = 0;
    compare(scene, compute_shadows(scene, options), penumbra::test::samples(200), random, tally,
            name);
  }
  BOOST_TEST_MESSAGE("oracle, degenerate fixtures: " << tally.compared << " points compared, "
                                                     << tally.on_boundary << " on a boundary, "
                                                     << tally.disagreements << " disagreements");
  BOOST_TEST(tally.compared >= std::size_t(penumbra::test::samples(5000)));
  BOOST_TEST(tally.disagreements == 0u);
}

BOOST_AUTO_TEST_CASE(broad_phase_and_range_culling_drop_no_shadow) {
  std::mt19937 random(11);  // fixed: reproducible scenes
  int scenes = 0;
  while (scenes < 10) {
    Scene scene;
    try {
      scene = scene_from_text(random_scene(random));
    } catch (const std::exception&) {
      continue;
    }
    ++scenes;
    ShadowOptions all_pairs;
    all_pairs.broad_phase = false;
    all_pairs.range_fraction = 0;
    const ShadowResult reference = compute_shadows(scene, all_pairs);
    ShadowOptions culled;  // a small sphere, r = sqrt(I_max / 50 lx): some faces beyond it
    culled.range_fraction = 1.0 / 10;
    const ShadowResult result = compute_shadows(scene, culled);
    for (std::size_t l = 0; l < result.lights.size(); ++l) {
      BOOST_TEST(result.lights[l].stats.pairs_tested <= reference.lights[l].stats.pairs_tested);
      for (std::size_t r = 0; r < result.receivers.size(); ++r) {
        const FaceShadow& a = reference.lights[l].faces[r];
        const FaceShadow& b = result.lights[l].faces[r];
        if (b.beyond_range) continue;
        BOOST_TEST((a.shadow == b.shadow));
        BOOST_TEST((a.lit == b.lit));
        BOOST_TEST(a.occluders.size() == b.occluders.size());
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(shadows_alone_are_the_full_runs_shadows) {
  // ShadowOptions::lit_parts = false (sun-hours) unites each face's shadows by groups and
  // skips the lit part: the shadows must be those of the full run, which the cases above
  // check against the oracle. Faces under two or more occluders take the Boolean path; the
  // mesh scenes' faces made of several pieces are united from their pieces' shadows alone.
  std::mt19937 random(29);  // fixed: reproducible scenes
  std::size_t united = 0;
  std::vector<Scene> scenes;
  for (const char* name :
       {"shadow-touching", "shadow-abutting", "shadow-collinear-contour", "shadow-shared-face",
        "shadow-sun-parallel", "mesh-canopy", "mesh-courtyard", "mesh-window", "mesh-through-hole",
        "mesh-noisy", "mesh-staircase"})
    scenes.push_back(load_scene(fixture(std::string("scenes/") + name + ".json")));
  // The L-shaped roof (one face of three pieces) partly in the shadow of a box above it.
  scenes.push_back(scene_from_text(
      "{\"penumbra\": 1, \"objects\": [{\"name\": \"house\", \"mesh\": \"" +
      fixture("meshes/l-courtyard.obj").string() +
      "\"}, {\"name\": \"box\", \"box\": {\"min\": [1, 1, 8], \"max\": [6, 3, 9]}}], "
      "\"lights\": [{\"name\": \"sun\", \"directional\": [0.125, 0.25, -1], \"illuminance\": "
      "1000}]}"));
  while (scenes.size() < 52) {
    try {
      scenes.push_back(scene_from_text(random_scene(random)));
    } catch (const std::exception&) {
      continue;
    }
  }
  for (const Scene& scene : scenes) {
    ShadowOptions full;
    full.range_fraction = 0;
    ShadowOptions alone = full;
    alone.lit_parts = false;
    const ShadowResult reference = compute_shadows(scene, full);
    const ShadowResult result = compute_shadows(scene, alone);
    for (std::size_t l = 0; l < result.lights.size(); ++l)
      for (std::size_t r = 0; r < result.receivers.size(); ++r) {
        const FaceShadow& a = reference.lights[l].faces[r];
        const FaceShadow& b = result.lights[l].faces[r];
        BOOST_TEST((a.shadow == b.shadow));
        BOOST_TEST(b.lit.empty());
        BOOST_TEST(a.occluders.size() == b.occluders.size());
        if (b.occluders.size() >= 2 && !a.lit.empty()) ++united;
      }
  }
  BOOST_TEST_MESSAGE("shadows alone: " << united << " faces under two or more shadows");
  BOOST_TEST(united >= 20u);
}

BOOST_AUTO_TEST_SUITE_END()
