#include "penumbra/shadow/face_shadow.h"

#include <algorithm>

#include <tuple>

#include "convex_difference.h"
#include "exact_compare.h"
#include "region_set.h"

namespace penumbra {
Ring2 face_ring(const Face& face) {
  return face.ring;
}

Region2 face_region(const Face& face) {
  // The ring has no repeated or collinear vertices (the face's are extreme points):
  // canonical once it starts at its lexicographically smallest vertex.
  Ring2 ring = face.ring;
  std::rotate(ring.begin(),
              std::min_element(ring.begin(), ring.end(),
                               [](const Point2& a, const Point2& b) {
                                 return CGAL::compare_xy(a, b) == CGAL::SMALLER;
                               }),
              ring.end());
  Region2 region;
  region.polygons.push_back({std::move(ring), {}});
  region.area = face.area;
  return region;
}

FaceShadow unlit_face(const Face& face) {
  FaceShadow result;
  result.faces_away = true;
  result.shadow = face_region(face);
  return result;
}

FaceShadow unite_shadows(const Face& face, std::vector<OccluderShadow> occluders, bool lit) {
  FaceShadow result;
  if (occluders.empty()) {
    if (lit) result.lit = face_region(face);
    return result;
  }
  const Ring2& ring = face.ring;
  // A shadow polygon that is the whole face makes the union the face and leaves
  // nothing lit (the polygons lie in the face): no Boolean operation is needed.
  Region2 whole = face_region(face);
  const Ring2* window = whole.empty() ? nullptr : &whole.polygons.front().outer;
  for (const OccluderShadow& occluder : occluders)
    if (window && detail::same_ring(occluder.polygon, *window)) {
      result.shadow = std::move(whole);
      result.occluders = std::move(occluders);
      return result;
    }
  std::vector<Ring2> polygons;
  for (const OccluderShadow& occluder : occluders) polygons.push_back(occluder.polygon);
  // Shadow polygons strictly apart are their own union, and the lit part then needs
  // no arrangement in the usual configurations (convex_difference.h).
  const auto groups = detail::touching_groups(polygons);
  if (!lit) {
    result.shadow = detail::unite_groups(polygons, groups);
    result.occluders = std::move(occluders);
    return result;
  }
  if (window && groups.size() == polygons.size()) {
    if (auto difference = detail::convex_difference(*window, polygons)) {
      std::vector<Polygon2> parts;
      for (const Ring2& polygon : polygons) parts.push_back({canonical_ring(polygon), {}});
      result.shadow = canonical_region(std::move(parts));
      result.lit = std::move(*difference);
      result.occluders = std::move(occluders);
      return result;
    }
  }
  // Section 3.2: the shadow areas on the face are the union of the shadows cast on it.
  std::tie(result.shadow, result.lit) = detail::unite_and_complement(polygons, groups, ring);
  result.occluders = std::move(occluders);
  return result;
}

}  // namespace penumbra
