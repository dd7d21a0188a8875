// The visible part of an area source from a point (shadow/source_view.h) against an exact
// per-point oracle written in the test: a point s of the source is visible from X when the
// segment from X to s meets no occluder's interior (linear_oracle.h). The rings returned add
// up, with their orientations as signs, to the visible part, so their winding sum at s must be
// 1 where s is visible and 0 where it is hidden, both by inclusion and exclusion (few hidden
// parts) and by the Boolean difference it falls back to (many overlapping ones).

#include <boost/test/unit_test.hpp>

#include <random>
#include <sstream>
#include <string>

#include "linear_oracle.h"
#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/source_view.h"
#include "shadow_support.h"

namespace {

using namespace penumbra;
using namespace penumbra::test;

// checks the winding sum of rings against the oracle at random points of the source.
void check_against_oracle(const Scene& scene, const Point3& x, std::mt19937& random,
                          std::size_t& checked, std::size_t& hidden) {
  const auto& panel = std::get<AreaLight>(scene.lights[0].source);
  const Face& source = panel.polygon->faces()[panel.front];
  std::vector<const ConvexPolyhedron*> occluders;
  for (const Object& object : scene.objects) occluders.push_back(&object.solid);
  const std::vector<Ring2> rings =
      visible_source(source, x, Plane3(x, Vector3(0, 0, 1)), occluders);
  for (int k = 0; k < 400; ++k) {
    const Point2 s = random_point(source.ring, random);
    int winding = 0;
    bool on_edge = false;
    for (const Ring2& ring : rings) {
      const auto side = CGAL::bounded_side_2(ring.begin(), ring.end(), s, Kernel());
      on_edge = on_edge || side == CGAL::ON_BOUNDARY;
      if (side == CGAL::ON_BOUNDED_SIDE) winding += signed_area(ring) > 0 ? 1 : -1;
    }
    if (on_edge) continue;
    const Point3 q = source.frame.to_world(s);
    bool blocked = false;
    for (const Object& object : scene.objects)
      blocked = blocked || segment_meets_interior(x, q, object.solid);
    BOOST_TEST(winding == (blocked ? 0 : 1), "source point " << k);
    ++checked;
    hidden += blocked;
  }
}

Scene scene_with(const std::string& objects) {
  return scene_from_text(
      R"({"penumbra": 1, "objects": [)" + objects +
      R"(], "lights": [{"name": "panel", "area": [[0,0,3],[0,2,3],[2,2,3],[2,0,3]],
                                          "luminance": 100}]})");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(source_view)

BOOST_AUTO_TEST_CASE(few_hidden_parts_by_inclusion_and_exclusion) {
  std::mt19937 random(2112);
  std::uniform_real_distribution<double> centre(0.6, 1.4), offset(-0.5, 0.5);
  std::size_t checked = 0, hidden = 0;
  for (int trial = 0; trial < 5; ++trial) {
    std::ostringstream objects;
    objects.precision(17);
    for (int k = 0; k < 3; ++k) {
      const double cx = centre(random), cy = centre(random);
      objects << (k ? "," : "") << R"({"name": "h)" << k << R"(", "convex": [)";
      for (int i = 0; i < 6; ++i)
        objects << (i ? "," : "") << "[" << cx + offset(random) << "," << cy + offset(random) << ","
                << 1.5 + offset(random) << "]";
      objects << "]}";
    }
    const Scene scene = scene_with(objects.str());
    check_against_oracle(scene, Point3(1, 1, 0), random, checked, hidden);
  }
  BOOST_TEST(checked > 1900);
  BOOST_TEST(hidden > 200);
  BOOST_TEST(checked - hidden > 200);
}

// Nine boxes that all overlap: 511 intersections, past the 64 rings inclusion and exclusion
// may make, so the Boolean difference answers (outer rings and holes: few rings).
BOOST_AUTO_TEST_CASE(many_overlapping_parts_by_the_boolean_difference) {
  std::ostringstream objects;
  for (int k = 0; k < 9; ++k) {
    const double shift = 0.05 * k;
    objects << (k ? "," : "") << R"({"name": "b)" << k << R"(", "box": {"min": [)" << 0.5 + shift
            << "," << 0.7 - shift << ",1.4], \"max\": [" << 0.9 + shift << "," << 1.1 - shift
            << ",1.6]}}";
  }
  const Scene scene = scene_with(objects.str());
  std::vector<const ConvexPolyhedron*> occluders;
  for (const Object& object : scene.objects) occluders.push_back(&object.solid);
  const auto& panel = std::get<AreaLight>(scene.lights[0].source);
  const Point3 x(1.1, 0.9, 0);
  BOOST_TEST(
      visible_source(panel.polygon->faces()[panel.front], x, Plane3(x, Vector3(0, 0, 1)), occluders)
          .size() <= 8);
  std::mt19937 random(77);
  std::size_t checked = 0, hidden = 0;
  check_against_oracle(scene, x, random, checked, hidden);
  BOOST_TEST(hidden > 50);
  BOOST_TEST(checked - hidden > 50);
}

BOOST_AUTO_TEST_SUITE_END()
