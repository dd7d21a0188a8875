#include "penumbra/shadow/area_face_shadow.h"

#include <algorithm>
#include <stdexcept>

#include "extended_face.h"
#include "half_plane.h"
#include "receiver_clip.h"

namespace penumbra {

AreaOcclusion area_occlusion(const ConvexPolyhedron& solid, const std::vector<Point3>& source) {
  AreaOcclusion result;
  try {
    result.volumes = area_volumes(solid, source);
  } catch (const std::domain_error&) {
    result.touches = true;
  }
  return result;
}

std::vector<Point3> source_part(const Face& source, const Plane3& plane) {
  // The kept side plane(X) > 0 is the closed half-space -plane(X) <= 0, closed at the cut.
  const Ring2 kept = detail::clip(source.ring, detail::restrict_to(plane.opposite(), source.frame));
  const auto ring = detail::ring_with_area(kept);
  std::vector<Point3> world;
  if (ring)
    for (const Point2& q : *ring) world.push_back(source.frame.to_world(q));
  return world;
}

FaceShadow area_face_shadow(const Face& face, const Face& source, bool two_sided,
                            const std::vector<AreaOccluder>& occluders) {
  const auto behind_source = [&](const Point3& p) {
    return source.plane.oriented_side(p) != CGAL::ON_POSITIVE_SIDE;
  };
  const std::vector<Point3> part = source_part(source, face.plane);
  if (part.empty() ||
      (!two_sided && std::all_of(face.vertices.begin(), face.vertices.end(), behind_source))) {
    // The whole source on or behind the face's plane, or the whole face behind a one-sided
    // source's: the face sees none of it.
    return detail::unlit_extended(face);
  }
  FaceShadow result;
  result.extended = true;
  result.source_clipped = std::any_of(
      source.vertices.begin(), source.vertices.end(),
      [&](const Point3& q) { return face.plane.oriented_side(q) != CGAL::ON_POSITIVE_SIDE; });
  const detail::ReceiverClip receiver(face);
  std::vector<Ring2> shadows, umbrae;
  for (const AreaOccluder& occluder : occluders) {
    const ConvexPolyhedron& solid = *occluder.solid;
    // Only the part of V strictly in front of the face's plane can block light.
    if (!detail::reaches_front(solid, face)) continue;
    std::optional<AreaOcclusion> own;
    if (!occluder.whole || result.source_clipped)
      own = area_occlusion(solid, result.source_clipped ? part : source.vertices);
    const AreaOcclusion& occlusion = own ? *own : *occluder.whole;
    if (occlusion.touches)
      throw std::domain_error("the area source touches or passes through an occluder");
    const std::optional<AreaVolumes>& volumes = occlusion.volumes;
    if (!volumes) continue;
    const auto polygon = receiver.clip(volumes->penumbra.planes);
    if (!polygon) continue;
    OccluderShadow shadow{occluder.id, *polygon};
    if (volumes->umbra) shadow.umbra = receiver.clip(volumes->umbra->planes);
    shadow.object_space = true;  // no loops: those are a linear source's (section 4.1.2)
    shadows.push_back(shadow.polygon);
    if (shadow.umbra) umbrae.push_back(*shadow.umbra);
    result.occluders.push_back(std::move(shadow));
  }
  result.joint_occlusion = detail::any_interiors_overlap(shadows);
  // A one-sided source lights nothing behind its plane: that part of the face is umbra.
  if (!two_sided)
    if (const auto behind = receiver.clip({source.plane})) {
      shadows.push_back(*behind);
      umbrae.push_back(*behind);
    }
  detail::fill_sets(result, shadows, umbrae, face);
  return result;
}

}  // namespace penumbra
