#include "penumbra/shadow/face_shadow.h"

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
  FaceShadow result;
  const Ring2 ring = face_ring(face);
  if (occluders.empty()) {
    result.lit = convex_region(ring);
    return result;
  }
  std::vector<Ring2> polygons;
  for (const OccluderShadow& occluder : occluders) polygons.push_back(occluder.polygon);
  // Section 3.2: the shadow areas on the face are the union of the shadows cast on it.
  result.shadow =
      polygons.size() == 1 ? convex_region(polygons.front()) : detail::unite_minus(polygons);
  result.lit = detail::unite_minus({ring}, polygons);
  result.occluders = std::move(occluders);
  return result;
}

}  // namespace penumbra
