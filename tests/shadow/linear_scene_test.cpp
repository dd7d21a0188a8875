// Whole scenes with linear sources through compute_shadows (issue #4 item 8a): on
// every face of the linear fixtures, rational sample points are classified by the
// exact oracles of linear_oracle.h, written independently of the engine, against
// the part of the source the face can see (its plane cuts the source, Fig. 7 S3).

#include <boost/test/unit_test.hpp>

#include <random>

#include "linear_oracle.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/shadow_map.h"
#include "solids.h"
#include "support/fixtures.h"

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

BOOST_AUTO_TEST_SUITE(linear_scene)

BOOST_AUTO_TEST_CASE(every_face_of_the_linear_fixtures_agrees_with_the_oracles) {
  std::mt19937 random(7);  // fixed: the sample points are part of the test
  std::uniform_int_distribution<int> weight(0, 8);
  int compared = 0, in_shadow = 0, in_umbra = 0;
  for (const char* name : {"linear-fig5", "linear-fig6", "linear-degenerate", "linear-joint",
                           "every-kind", "office"}) {
    const Scene scene = load_scene(test::fixture(std::string("scenes/") + name + ".json"));
    const ShadowResult result = compute_shadows(scene);
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
        for (int s = 0; s < 40; ++s) {
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
          for (std::size_t o = 0; o < scene.objects.size(); ++o) {
            if (o == result.receivers[r].object) continue;
            const ConvexPolyhedron& solid = scene.objects[o].solid;
            blocked =
                blocked || test::source_partly_blocked(x, source->first, source->second, solid);
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
  BOOST_TEST_MESSAGE("linear scenes: " << compared << " points, " << in_shadow << " in shadow, "
                                       << in_umbra << " in umbra");
  BOOST_TEST(in_shadow > 100);
  BOOST_TEST(in_umbra > 20);
}

BOOST_AUTO_TEST_SUITE_END()
