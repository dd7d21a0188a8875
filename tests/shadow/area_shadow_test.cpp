#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "linear_oracle.h"
#include "penumbra/base/input_error.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/shadow_map.h"
#include "shadow_support.h"
#include "support/heavy.h"

namespace {

using namespace penumbra;
using namespace penumbra::test;

// returns true when the interiors of two convex solids meet: then either one lies in the
// other, or the boundary of one meets the other's interior (a point of both interiors and a
// point of one outside the other bound a segment whose exit point lies in both). Written
// with the Sutherland-Hodgman clip of linear_oracle.h, not the engine's volumes.
bool interiors_meet(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const auto centre_inside = [](const ConvexPolyhedron& x, const ConvexPolyhedron& y) {
    return clipped_meets_interior(x.vertices(), y);
  };
  if (centre_inside(a, b) || centre_inside(b, a)) return true;
  for (const auto* pair : {&a, &b}) {
    const ConvexPolyhedron& x = *pair;
    const ConvexPolyhedron& y = pair == &a ? b : a;
    for (const Face& face : x.faces())
      if (simplex_meets_interior(face.vertices, y)) return true;
  }
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(area_shadow)

// Shadow sets of an area source against per-point exact oracles on random scenes (fixed
// seeds): a point X of the floor is in the shadow of a solid V when the pyramid conv(X, S)
// meets V's interior (some segment from X to the source is blocked), and in its umbra when
// every segment from X to a vertex of S is (the part of S that V hides from X is convex, so
// it is then all of S). The map's shadow is the union over solids, its umbra the union of
// the single solids' umbrae. Points on a boundary are skipped (closed sets: either answer).
BOOST_AUTO_TEST_CASE(sets_against_point_oracles_on_random_scenes) {
  std::mt19937 random(4242);
  std::uniform_real_distribution<double> centre(0.8, 3.2), height(0.7, 1.9), offset(-0.8, 0.8);
  int checked = 0, umbra = 0, penumbra = 0;
  for (int scene_index = 0; scene_index < 6; ++scene_index) {
    std::ostringstream text;
    text.precision(17);
    text << R"({"penumbra": 1, "objects": [{"name": "floor", "box": {"min": [-2,-2,-1], )"
         << R"("max": [6,6,0]}})";
    for (int k = 0; k < 4; ++k) {
      const double x = centre(random), y = centre(random), z = height(random);
      text << R"(, {"name": "s)" << k << R"(", "convex": [)";
      for (int i = 0; i < 7; ++i)
        text << (i ? "," : "") << "[" << x + offset(random) << "," << y + offset(random) << ","
             << z + offset(random) / 2 << "]";
      text << "]}";
    }
    // A tilted quadrilateral panel (exactly planar: a parallelogram), facing down.
    text << R"(], "lights": [{"name": "panel", "area": [[1.2,1.5,3.1],[1.7,2.6,3.1],)"
         << R"([2.9,2.6,3.4],[2.4,1.5,3.4]], "luminance": 500}]})";
    const Scene scene = scene_from_text(text.str());
    const ShadowResult result = compute_shadows(scene);
    const FaceShadow& floor = shadow_of(scene, result, "panel", "floor", Vector3(0, 0, 1));
    const Face& face = face_along(scene, "floor", Vector3(0, 0, 1));
    const auto& panel = std::get<AreaLight>(scene.lights[0].source);
    const std::vector<Point3>& source = panel.polygon->faces()[panel.front].vertices;
    BOOST_TEST(floor.extended);
    for (int k = 0; k < penumbra::test::samples(300); ++k) {
      // Half the points anywhere on the floor, half under the solids.
      const Point2 q = k % 2 ? random_point(face.ring, random)
                             : face.frame.to_frame(Point3(centre(random), centre(random), 0));
      const Point3 x = face.frame.to_world(q);
      std::vector<Point3> pyramid = source;
      pyramid.push_back(x);
      const ConvexPolyhedron cone = ConvexPolyhedron::hull(pyramid);
      bool in_shadow = false, in_umbra = false;
      for (const Object& object : scene.objects) {
        if (object.name == "floor") continue;
        in_shadow = in_shadow || interiors_meet(cone, object.solid);
        in_umbra = in_umbra || std::all_of(source.begin(), source.end(), [&](const Point3& s) {
                     return segment_meets_interior(x, s, object.solid);
                   });
      }
      const Where shadow = locate(floor.shadow, q), dark = locate(floor.umbra, q);
      if (shadow == Where::boundary || dark == Where::boundary) continue;
      ++checked;
      BOOST_TEST((shadow == Where::inside) == in_shadow, "scene " << scene_index << " point " << k);
      BOOST_TEST((dark == Where::inside) == in_umbra, "scene " << scene_index << " point " << k);
      umbra += in_umbra;
      penumbra += in_shadow && !in_umbra;
    }
  }
  BOOST_TEST(checked > penumbra::test::samples(1700));
  BOOST_TEST(umbra > penumbra::test::samples(20));
  BOOST_TEST(penumbra > penumbra::test::samples(100));
}

// A one-sided panel lights nothing behind its plane: a wall rising through the panel's plane
// is umbra above it; the panel's back lights nothing; a panel touching a shadowing solid is
// refused by name.
BOOST_AUTO_TEST_CASE(behind_the_source_and_touching) {
  const Scene scene = scene_from_text(
      R"({"penumbra": 1, "objects": [{"name": "wall", "box": {"min": [3,0,0], "max": [3.2,4,4]}}],
          "lights": [{"name": "panel", "area": [[1,1,3],[1,2,3],[2,2,3],[2,1,3]], "luminance": 10}]})");
  const ShadowResult result = compute_shadows(scene);
  const FaceShadow& wall = shadow_of(scene, result, "panel", "wall", Vector3(-1, 0, 0));
  const Face& face = face_along(scene, "wall", Vector3(-1, 0, 0));
  // The wall's face x = 3 is 4 x 4; the part above z = 3 (4 x 1) is umbra, the rest is lit.
  BOOST_TEST(world_area_is(wall.umbra, face, Exact(4)));
  BOOST_TEST(world_area_is(wall.lit, face, Exact(12)));
  BOOST_TEST(wall.penumbra.empty());

  const Scene touching = scene_from_text(
      R"({"penumbra": 1, "objects": [{"name": "floor", "box": {"min": [-5,-5,-1], "max": [5,5,0]}},
          {"name": "beam", "box": {"min": [1.5,0,2], "max": [1.8,4,3]}}],
          "lights": [{"name": "panel", "area": [[1,1,3],[1,2,3],[2,2,3],[2,1,3]], "luminance": 10}]})");
  BOOST_CHECK_EXCEPTION(compute_shadows(touching), InputError, [](const InputError& e) {
    return std::string(e.what()).find("touches or passes through") != std::string::npos;
  });
}

BOOST_AUTO_TEST_SUITE_END()
