// The solver's shortcuts give the plain solver's answers: occluder lists taken from the
// exact shadow maps, and the interval filters in front of every exact test (against the
// exact oracle at random points).

#include <boost/test/unit_test.hpp>

#include <random>

#include "penumbra/illuminance/linear_source.h"
#include "penumbra/shadow/shadow_map.h"
#include "scene_support.h"

using namespace penumbra;
using namespace penumbra::illuminance;
using penumbra::test::oracle_meets_interior;
using penumbra::test::oracle_segment_blocked;
using penumbra::test::scene_from;

BOOST_AUTO_TEST_SUITE(solver_shortcuts)

// The query with known occluders (the renderer's fast path): for each face, the objects
// whose exact shadow meets it (FaceShadow::occluders) are given as the only occluders.
// At random points of every face, lifted 1e-9 (1 + |P|) off it as the renderer lifts
// them, the answer equals the full query: per light within 1e-9 relative. Random weights
// stay >= 0.02 so no point is within rounding of a face edge, where the lifted point may
// see past the face's own shadow map (the tie class docs/illuminance.md names).
BOOST_AUTO_TEST_CASE(occluders_from_the_shadow_maps_give_the_full_answer) {
  std::mt19937 random(7);  // fixed: the same points on every run
  std::uniform_real_distribution<double> weight(0.02, 1);
  for (const char* name : {"scenes/office.json", "scenes/linear-joint.json"}) {
    const Scene scene = load_scene(test::fixture(name));
    const IlluminanceSolver solver(scene);
    ShadowOptions options;
    options.range_fraction = 0;
    options.unite_mesh_faces = false;  // each piece's face against the solver
    const ShadowResult shadows = compute_shadows(scene, options);
    std::size_t compared = 0, differ = 0, shadowed = 0, lit_beside_shadow = 0, unrestricted = 0;
    for (std::size_t r = 0; r < shadows.receivers.size(); ++r) {
      const Receiver& receiver = shadows.receivers[r];
      const Face& face = scene.objects[receiver.object].solid.faces()[receiver.face];
      std::vector<std::vector<std::size_t>> occluders(scene.lights.size());
      for (const LightShadows& light : shadows.lights)
        for (const OccluderShadow& shadow : light.faces[r].occluders)
          occluders[light.light].push_back(shadow.occluder);
      const Vec3d normal =
          to_double(face.normal() / std::sqrt(CGAL::to_double(face.normal().squared_length())));
      for (int k = 0; k < 40; ++k) {
        Vec3d p{0, 0, 0};
        double total = 0;
        for (const Point3& vertex : face.vertices) {
          const double w = weight(random);
          const Vec3d v = to_double(vertex);
          for (int i = 0; i < 3; ++i) p[i] += w * v[i];
          total += w;
        }
        for (int i = 0; i < 3; ++i) p[i] /= total;
        const double lift = 1e-9 * (1 + std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}));
        for (int i = 0; i < 3; ++i) p[i] += lift * normal[i];
        const PointIlluminance full = solver.at(p, normal);
        const PointIlluminance fast = solver.at(p, normal, occluders);
        BOOST_TEST(fast.inside.has_value() == full.inside.has_value());
        for (std::size_t light = 0; light < scene.lights.size(); ++light) {
          ++compared;
          const double expected = full.per_light[light];
          if (std::abs(fast.per_light[light] - expected) > 1e-9 * std::abs(expected)) {
            if (++differ <= 5)
              BOOST_TEST_MESSAGE(name << " face " << r << " light " << light << ": "
                                      << fast.per_light[light] << " vs " << expected);
          }
          if (occluders[light].empty()) continue;
          // What the lists leave out matters: without them the point is lit.
          const double unoccluded =
              solver.at(p, normal, std::vector<std::vector<std::size_t>>(scene.lights.size()))
                  .per_light[light];
          if (unoccluded > expected) {
            ++shadowed;
            unrestricted += fast.per_light[light] == unoccluded;
          } else if (expected > 0) {
            ++lit_beside_shadow;
          }
        }
      }
    }
    BOOST_TEST_MESSAGE(name << ": " << compared << " values, " << shadowed << " shadowed, "
                            << lit_beside_shadow << " lit on shadowed faces, " << differ
                            << " differ");
    BOOST_TEST(differ == 0u, name);
    BOOST_TEST(shadowed > 10u, name);
    BOOST_TEST(lit_beside_shadow > 10u, name);
    BOOST_TEST(unrestricted == 0u, name);
  }
}

// The interval filters and culls in front of the exact tests decide as the exact oracle
// does: at random points and normals in the default scene, each point light and the sun
// give 0 exactly when an object meets the open segment (ray), and otherwise what they
// give with no objects at all; a random point Q(u) of the tube lies in a visible part
// exactly when it is strictly on the outer side and no object meets the segment P Q(u).
BOOST_AUTO_TEST_CASE(filtered_occlusion_follows_the_exact_oracle_at_random_points) {
  const Scene scene = load_scene(test::fixture("scenes/office.json"));
  Scene bare = scene;
  bare.objects.clear();
  const IlluminanceSolver solver(scene), unoccluded(bare);
  std::mt19937 random(11);  // fixed: the same points on every run
  std::uniform_real_distribution<double> x(0, 6), y(0, 4), z(0, 3), c(-1, 1);
  std::uniform_real_distribution<double> along(0, 1);
  int blocked_count = 0, seen_count = 0, tube_hidden = 0, tube_seen = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3d p{x(random), y(random), z(random)};
    Vec3d n{c(random), c(random), c(random)};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length < 0.1) continue;
    for (double& component : n) component /= length;
    if (solver.containing_object(p)) continue;
    for (std::size_t light = 0; light < scene.lights.size(); ++light) {
      bool blocked = false;
      if (const auto* lamp = std::get_if<PointLight>(&scene.lights[light].source)) {
        for (const Object& object : scene.objects)
          blocked = blocked ||
                    oracle_segment_blocked(object.solid, to_exact(p), to_exact(lamp->position));
      } else if (const auto* sun = std::get_if<DirectionalLight>(&scene.lights[light].source)) {
        const Vector3 toward = -to_exact_vector(sun->direction);
        for (const Object& object : scene.objects)
          blocked = blocked || oracle_meets_interior(object.solid, to_exact(p), toward, {});
      } else {
        if (k % 6 != 0) continue;  // the oracle is slow: 500 points, 8 source points each
        const auto& tube = std::get<LinearLight>(scene.lights[light].source);
        const std::vector<ExactInterval> parts = solver.visible_parts(light, p, n);
        for (int sample = 0; sample < 8; ++sample) {
          const Exact u(along(random));
          const Point3 q = to_exact(tube.start) + u * (to_exact(tube.end) - to_exact(tube.start));
          bool seen = CGAL::is_positive(to_exact_vector(n) * (q - to_exact(p)));
          for (const Object& object : scene.objects)
            seen = seen && !oracle_segment_blocked(object.solid, to_exact(p), q);
          const bool in_part = std::any_of(
              parts.begin(), parts.end(),
              [&](const ExactInterval& part) { return part.low <= u && u <= part.high; });
          BOOST_TEST(in_part == seen);
          (seen ? tube_seen : tube_hidden) += 1;
        }
        continue;
      }
      const double free = unoccluded.light_at(light, p, n);
      if (free == 0) continue;
      BOOST_TEST(solver.light_at(light, p, n) == (blocked ? 0.0 : free));
      (blocked ? blocked_count : seen_count) += 1;
    }
  }
  BOOST_TEST(blocked_count > 100);
  BOOST_TEST(seen_count > 100);
  BOOST_TEST(tube_hidden > 100);
  BOOST_TEST(tube_seen > 100);
}

// The tube's visible parts decided in intervals (hidden_interval_filter and the interval
// union) give the value of the exact path: the exact visible parts (visible_parts, built
// with Epeck) integrated by the same closed form, to 1e-12 relative. A block of boxes of
// several heights under a tube, as in the city benchmark (roofs at the tube's height
// among them), at random points on and between them with random normals.
BOOST_AUTO_TEST_CASE(interval_filtered_tube_equals_the_exact_path) {
  std::string objects;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = 10.0 * i, y = 10.0 * j, height = 3.0 * (2 + (i * 3 + j * 5) % 5);
      objects += std::string(objects.empty() ? "" : ",") + R"({"name": "b)" +
                 std::to_string(i * 4 + j) + R"(", "box": {"min": [)" + std::to_string(x + 2) +
                 ", " + std::to_string(y + 2) + R"(, 0], "max": [)" + std::to_string(x + 8) + ", " +
                 std::to_string(y + 8) + ", " + std::to_string(height) + "]}}";
    }
  const Scene scene = scene_from(
      objects,
      R"({"name": "tube", "linear": [[15, 20, 6], [25, 20, 6]], "candela_per_metre": 300})");
  const auto& tube = std::get<LinearLight>(scene.lights[0].source);
  const IlluminanceSolver solver(scene);
  std::mt19937 random(5);  // fixed: the same points on every run
  std::uniform_real_distribution<double> xy(-5, 45), z(0, 14), c(-1, 1);
  int compared = 0, partly_hidden = 0;
  for (int k = 0; k < 4000; ++k) {
    // Half the points on the ground (normal up), half anywhere with random normals.
    Vec3d p{xy(random), xy(random), k % 2 ? z(random) : 1e-9};
    Vec3d n{0, 0, 1};
    if (k % 2) {
      n = {c(random), c(random), c(random)};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (length < 0.1) continue;
      for (double& component : n) component /= length;
    }
    if (solver.containing_object(p)) continue;
    const std::vector<ExactInterval> exact_parts = solver.visible_parts(0, p, n);
    std::vector<SourceInterval> parts;
    for (const ExactInterval& part : exact_parts)
      parts.emplace_back(CGAL::to_double(part.low), CGAL::to_double(part.high));
    const double exact = parts.empty() ? 0.0
                                       : linear_illuminance(p, n, tube.start, tube.end,
                                                            tube.candela_per_metre, parts);
    const double filtered = solver.light_at(0, p, n);
    BOOST_TEST(std::abs(filtered - exact) <= 1e-12 * std::abs(exact), "at point " << k);
    ++compared;
    const auto outer = outer_side_interval(p, n, tube.start, tube.end);
    if (!parts.empty() && outer &&
        (parts.size() > 1 || parts.front().first > outer->first ||
         parts.front().second < outer->second))
      ++partly_hidden;
  }
  BOOST_TEST(compared > 3000);
  BOOST_TEST(partly_hidden > 200);
}

BOOST_AUTO_TEST_SUITE_END()
