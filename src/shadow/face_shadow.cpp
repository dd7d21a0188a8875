#include "penumbra/shadow/face_shadow.h"

#include <tuple>

#include "convex_difference.h"
#include "exact_compare.h"
#include "region_set.h"

namespace penumbra {
Ring2 face_ring(const Face& face) {
  Ring2 ring;
  for (const Point3& p : face.vertices) ring.push_back(face.frame.to_frame(p));
  return ring;
}

FaceShadow unlit_face(const Face& face) {
  FaceShadow result;
  result.faces_away = true;
  result.shadow = convex_region(face_ring(face));
  return result;
}

FaceShadow unite_shadows(const Face& face, std::vector<OccluderShadow> occluders) {
  return unite_shadows(face_ring(face), std::move(occluders));
}

FaceShadow unite_shadows(const Ring2& ring, std::vector<OccluderShadow> occluders) {
  FaceShadow result;
  if (occluders.empty()) {
    result.lit = convex_region(ring);
    return result;
  }
  // A shadow polygon that is the whole face makes the union the face and leaves
  // nothing lit (the polygons lie in the face): no Boolean operation is needed.
  Region2 whole = convex_region(ring);
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
  bool apart = window != nullptr;
  for (std::size_t i = 0; apart && i < polygons.size(); ++i)
    for (std::size_t j = i + 1; apart && j < polygons.size(); ++j)
      apart = detail::strictly_apart(polygons[i], polygons[j]);
  if (apart) {
    if (auto lit = detail::convex_difference(*window, polygons)) {
      std::vector<Polygon2> parts;
      for (const Ring2& polygon : polygons) parts.push_back({canonical_ring(polygon), {}});
      result.shadow = canonical_region(std::move(parts));
      result.lit = std::move(*lit);
      result.occluders = std::move(occluders);
      return result;
    }
  }
  // Section 3.2: the shadow areas on the face are the union of the shadows cast on it.
  std::tie(result.shadow, result.lit) = detail::unite_and_complement(polygons, ring);
  result.occluders = std::move(occluders);
  return result;
}

}  // namespace penumbra
