// Whole scenes with linear sources through compute_shadows (issue #4 item 8a): on
// every face of the linear fixtures, rational sample points are classified by the
// exact oracles of linear_oracle.h, written independently of the engine, against
// the part of the source the face can see (its plane cuts the source, Fig. 7 S3).

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "linear_oracle.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/shadow_map.h"
#include "solids.h"
#include "support/fixtures.h"
#include "support/heavy.h"

using namespace penumbra;

namespace {

using test::side_of;

// returns the visible part of the source for a face, written out independently:
// the source's points with F > 0, closed at the cut; nullopt when none.
std::optional<std::pair<Point3, Point3>> visible_part(const Face& face, Point3 q1, Point3 q2) {
  const Exact f1 = test::plane_value(face.plane, q1), f2 = test::plane_value(face.plane, q2);
  if (f1 <= 0 && f2 <= 0) return std::nullopt;
  const Point3 cut = q1 + (f1 / (f1 - f2)) * (q2 - q1);
  if (f1 <= 0) q1 = cut;
  if (f2 <= 0) q2 = cut;
  return std::make_pair(q1, q2);
}

}  // namespace

namespace {

// Counts of the sample points a scene's linear sources were checked at.
struct Counts {
  int compared = 0, in_shadow = 0, in_umbra = 0;
};

// checks every receiving face of scene under its linear sources against the oracles at
// points_per_face rational points each (faces of mesh pieces one by one: options keep the pieces).
void check_linear_scene(const Scene& scene, const ShadowOptions& options, const std::string& name,
                        std::mt19937& random, Counts& counts, int points_per_face = 40) {
  std::uniform_int_distribution<int> weight(0, 8);
  int& compared = counts.compared;
  int& in_shadow = counts.in_shadow;
  int& in_umbra = counts.in_umbra;
  const ShadowResult result = compute_shadows(scene, options);
  // Boxes that hold each object (from intervals, so never too small): an object whose box
  // misses the box of the triangle (x, q1, q2) cannot meet a segment from x to the source.
  std::vector<CGAL::Bbox_3> boxes;
  for (const Object& object : scene.objects) {
    CGAL::Bbox_3 box;
    for (const Point3& v : object.solid.vertices()) box += v.bbox();
    boxes.push_back(box);
  }
  for (const LightShadows& light : result.lights) {
    const auto* tube = std::get_if<LinearLight>(&scene.lights[light.light].source);
    if (!tube) continue;
    for (std::size_t r = 0; r < result.receivers.size(); ++r) {
      const Object& object = scene.objects[result.receivers[r].object];
      const Face& face = object.solid.faces()[result.receivers[r].face];
      const FaceShadow& shadow = light.faces[r];
      if (shadow.beyond_range) continue;  // culled: not computed
      const auto source = visible_part(face, to_exact(tube->start), to_exact(tube->end));
      BOOST_TEST(shadow.faces_away == !source.has_value());
      if (!source) continue;
      for (int s = 0; s < points_per_face; ++s) {
        // A random rational point of the face: a convex combination of its vertices.
        Vector3 sum = CGAL::NULL_VECTOR;
        int total = 0;
        for (const Point3& v : face.vertices) {
          const int w = weight(random);
          sum = sum + w * (v - CGAL::ORIGIN);
          total += w;
        }
        if (total == 0) continue;
        const Point3 x = CGAL::ORIGIN + sum / total;
        bool blocked = false, umbra = false;
        const CGAL::Bbox_3 reach = x.bbox() + source->first.bbox() + source->second.bbox();
        for (std::size_t o = 0; o < scene.objects.size(); ++o) {
          if (o == result.receivers[r].object || !CGAL::do_overlap(boxes[o], reach)) continue;
          const ConvexPolyhedron& solid = scene.objects[o].solid;
          blocked = blocked || test::source_partly_blocked(x, source->first, source->second, solid);
          umbra = umbra || (test::point_blocked(x, source->first, solid) &&
                            test::point_blocked(x, source->second, solid));
        }
        const Point2 p = face.frame.to_frame(x);
        const auto shadow_side = side_of(shadow.shadow, p), umbra_side = side_of(shadow.umbra, p);
        if (shadow_side == CGAL::ON_BOUNDED_SIDE) BOOST_TEST(blocked, name << " " << object.name);
        if (shadow_side == CGAL::ON_UNBOUNDED_SIDE)
          BOOST_TEST(!blocked, name << " " << object.name << " face " << result.receivers[r].face
                                    << " light " << scene.lights[light.light].name << " x " << x);
        if (umbra_side == CGAL::ON_BOUNDED_SIDE)
          BOOST_TEST(umbra, name << " " << object.name << " face " << result.receivers[r].face
                                 << " light " << scene.lights[light.light].name << " x " << x);
        if (umbra_side == CGAL::ON_UNBOUNDED_SIDE) BOOST_TEST(!umbra, name << " " << object.name);
        ++compared;
        in_shadow += blocked;
        in_umbra += umbra;
      }
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_scene)

BOOST_AUTO_TEST_CASE(every_face_of_the_linear_fixtures_agrees_with_the_oracles) {
  std::mt19937 random(7);  // fixed: the sample points are part of the test
  Counts counts;
  for (const char* name :
       {"linear-fig5", "linear-fig6", "linear-degenerate", "linear-joint", "every-kind", "office"})
    check_linear_scene(load_scene(test::fixture(std::string("scenes/") + name + ".json")), {}, name,
                       random, counts);
  const int compared = counts.compared, in_shadow = counts.in_shadow, in_umbra = counts.in_umbra;
  BOOST_TEST_MESSAGE("linear scenes: " << compared << " points, " << in_shadow << " in shadow, "
                                       << in_umbra << " in umbra");
  BOOST_TEST(in_shadow > 100);
  BOOST_TEST(in_umbra > 20);
}

BOOST_AUTO_TEST_CASE(mesh_pieces_under_a_tube_agree_with_the_oracles) {
  // The real-model fixtures with a 0.78 m tube in place of each point lamp (along x, beside
  // it): every receiving face of every convex piece (the pieces kept apart: the oracle works
  // on convex occluders) against the oracles, the other pieces of the same model included.
  std::mt19937 random(11);
  Counts counts;
  for (const char* name :
       {"mesh-courtyard", "mesh-through-hole", "mesh-staircase", "mesh-window", "mesh-canopy"}) {
    const auto fixture = test::fixture(std::string("scenes/") + name + ".json");
    nlohmann::json document = nlohmann::json::parse(std::ifstream(fixture));
    for (auto& object : document.at("objects"))
      if (object.contains("mesh"))
        object["mesh"] = (fixture.parent_path() / object["mesh"].get<std::string>()).string();
    for (auto& light : document.at("lights"))
      if (light.contains("point")) {
        const auto p = light["point"].get<std::array<double, 3>>();
        light.erase("point");
        light.erase("candela");
        // ends off the models' planes (their coordinates are short decimals)
        light["linear"] = {{p[0] - 0.37, p[1] + 0.013, p[2] + 0.011},
                           {p[0] + 0.41, p[1] + 0.013, p[2] + 0.011}};
        light["candela_per_metre"] = 300;
      }
    const auto path = test::scratch_dir(std::string("linear-") + name) / "scene.json";
    std::ofstream(path) << document.dump();
    ShadowOptions options;
    options.unite_mesh_faces = false;
    check_linear_scene(load_scene(path), options, name, random, counts);
  }
  BOOST_TEST_MESSAGE("mesh pieces under tubes: " << counts.compared << " points, "
                                                 << counts.in_shadow << " in shadow, "
                                                 << counts.in_umbra << " in umbra");
  BOOST_TEST(counts.in_shadow > 100);
  BOOST_TEST(counts.in_umbra > 20);
}

BOOST_AUTO_TEST_CASE(ifc_house_under_a_tube_agrees_with_the_oracles, PENUMBRA_HEAVY_TEST) {
  // The KIT house (fixtures/meshes/AC14-FZK-Haus.ifc.gz, "up": "y", as in mesh_oracle_test)
  // with a 4 m tube east of it at 3.1 m, parallel to its east wall: the ground's top and the
  // pieces of the east façade (the eaves, the windows' frames and reveals shade the wall),
  // each against the oracles at 12 points.
  const auto path = test::gunzip_fixture("meshes/AC14-FZK-Haus.ifc");
  nlohmann::json document = {
      {"penumbra", 1},
      {"objects",
       {{{"name", "ground"}, {"box", {{"min", {-15, -15, -2}}, {"max", {30, 30, -1}}}}},
        {{"name", "house"}, {"mesh", path.string()}, {"up", "y"}}}},
      {"lights",
       {{{"name", "tube"},
         {"linear", {{18, 3.013, 3.111}, {18, 7.013, 3.111}}},
         {"candela_per_metre", 150}}}}};
  const auto file = test::scratch_dir("linear-ifc-house") / "scene.json";
  std::ofstream(file) << document.dump();
  const Scene scene = load_scene(file);
  ShadowOptions options;
  options.unite_mesh_faces = false;
  options.range_fraction = 0;
  std::vector<Receiver> receivers;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto& faces = scene.objects[o].solid.faces();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const bool ground_top = o == 0 && faces[f].plane == Plane3(0, 0, 1, 1);
      // The east façade: faces turned east with every vertex at x >= 11.8 (the wall's
      // outer plane is x = 12, its windows' frames at 11.88, the eaves at 12.5).
      const bool east = o > 0 && CGAL::is_positive(faces[f].plane.orthogonal_vector().x()) &&
                        std::all_of(faces[f].vertices.begin(), faces[f].vertices.end(),
                                    [](const Point3& v) { return v.x() >= Exact(11.8); });
      if (ground_top || east) receivers.push_back({o, f});
    }
  }
  // Every 20th of the façade's pieces (600-odd), so that the test stays short.
  std::vector<Receiver> chosen;
  for (std::size_t k = 0; k < receivers.size(); ++k)
    if (k == 0 || k % 20 == 1) chosen.push_back(receivers[k]);
  BOOST_TEST_REQUIRE(chosen.size() >= 20u);
  options.receivers = chosen;
  std::mt19937 random(17);
  Counts counts;
  check_linear_scene(scene, options, "ifc-house", random, counts, 12);
  BOOST_TEST_MESSAGE("IFC house under a tube: " << counts.compared << " points, "
                                                << counts.in_shadow << " in shadow, "
                                                << counts.in_umbra << " in umbra");
  BOOST_TEST(counts.in_shadow > 100);
  BOOST_TEST(counts.in_umbra > 20);
  BOOST_TEST(counts.compared - counts.in_shadow > 20);  // lit points too
}

BOOST_AUTO_TEST_SUITE_END()
