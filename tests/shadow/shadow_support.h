#pragma once
// Helpers shared by the shadow tests: point classification against a region,
// random rational points of a face, and scene construction from JSON text.

#include <boost/test/unit_test.hpp>

#include <optional>
#include <random>
#include <string>
#include <vector>

#include <CGAL/Polygon_2_algorithms.h>

#include "penumbra/scene/load_scene.h"
#include "penumbra/shadow/region_overlay.h"
#include "penumbra/shadow/shadow_map.h"

namespace penumbra::test {

enum class Where { inside, boundary, outside };

// returns where p lies relative to a region's polygons (closed sets, exact).
inline Where locate(const Region2& region, const Point2& p) {
  for (const Polygon2& polygon : region.polygons) {
    const auto outer =
        CGAL::bounded_side_2(polygon.outer.begin(), polygon.outer.end(), p, Kernel());
    if (outer == CGAL::ON_BOUNDARY) return Where::boundary;
    if (outer == CGAL::ON_UNBOUNDED_SIDE) continue;
    bool in_hole = false;
    for (const Ring2& hole : polygon.holes) {
      const auto side = CGAL::bounded_side_2(hole.begin(), hole.end(), p, Kernel());
      if (side == CGAL::ON_BOUNDARY) return Where::boundary;
      if (side == CGAL::ON_BOUNDED_SIDE) in_hole = true;
    }
    if (!in_hole) return Where::inside;
  }
  return Where::outside;
}

// returns how many of regions hold p inside, or nothing when p lies on one's boundary (a
// count read from an overlay is then ambiguous).
inline std::optional<std::size_t> regions_holding(const std::vector<Region2>& regions,
                                                  const Point2& p) {
  std::size_t holding = 0;
  for (const Region2& region : regions) {
    const Where where = locate(region, p);
    if (where == Where::boundary) return std::nullopt;
    holding += where == Where::inside;
  }
  return holding;
}

// checks that exactly one of parts (an overlay's parts, tiling a window) holds p inside, and
// that its count is expected.
inline void check_one_part_holds(const std::vector<Coverage>& parts, const Point2& p,
                                 std::size_t expected) {
  std::size_t holding = 0;
  for (const Coverage& part : parts)
    if (locate(part.region, p) == Where::inside) {
      ++holding;
      BOOST_TEST(part.count == expected);
    }
  BOOST_TEST(holding == 1u);
}

// returns a random point strictly inside a convex face, in its frame: a convex
// combination of its vertices with random positive integer weights.
// Weights of random magnitude (up to 2^20) spread the points toward edges and corners.
inline Point2 random_point(const Ring2& ring, std::mt19937& random) {
  std::uniform_int_distribution<int> exponent(0, 20);
  Exact x = 0, y = 0, total = 0;
  for (const Point2& p : ring) {
    const Exact w = std::uniform_int_distribution<int>(1, 1 << exponent(random))(random);
    x += w * p.x();
    y += w * p.y();
    total += w;
  }
  return Point2(x / total, y / total);
}

inline Scene scene_from_text(const std::string& text) {
  return parse_scene(text, "generated.json");
}

// returns the face of object whose outward normal points along direction.
inline const Face& face_along(const Scene& scene, const std::string& object,
                              const Vector3& direction) {
  const Object* found = scene.find_object(object);
  BOOST_TEST_REQUIRE(found != nullptr, object);
  for (const Face& face : found->solid.faces())
    if (CGAL::cross_product(face.normal(), direction) == CGAL::NULL_VECTOR &&
        face.normal() * direction > 0)
      return face;
  BOOST_FAIL("no face of " << object << " along the direction");
  throw;
}

// returns the shadow map of the face of object along direction, under light.
inline const FaceShadow& shadow_of(const Scene& scene, const ShadowResult& result,
                                   const std::string& light, const std::string& object,
                                   const Vector3& direction) {
  const Face& face = face_along(scene, object, direction);
  for (const LightShadows& shadows : result.lights) {
    if (scene.lights[shadows.light].name != light) continue;
    for (std::size_t r = 0; r < result.receivers.size(); ++r) {
      const Receiver& receiver = result.receivers[r];
      if (&scene.objects[receiver.object].solid.faces()[receiver.face] == &face)
        return shadows.faces[r];
    }
  }
  BOOST_FAIL("no result for light " << light << " on " << object);
  throw;
}

// returns true when the region's world area is exactly expected: the frame area
// times |u| |v|, compared squared so that no square root is taken.
inline bool world_area_is(const Region2& region, const Face& face, const Exact& expected) {
  const Exact uu = face.frame.u() * face.frame.u();
  const Exact vv = face.frame.v() * face.frame.v();
  return region.area >= 0 && region.area * region.area * uu * vv == expected * expected;
}

// returns the occluder shadow polygon of the named object on a face map, as a region.
inline Region2 occluder_region(const Scene& scene, const FaceShadow& shadow,
                               const std::string& object) {
  for (const OccluderShadow& occluder : shadow.occluders)
    if (scene.objects[occluder.occluder].name == object) return convex_region(occluder.polygon);
  return {};
}

}  // namespace penumbra::test
