#include "penumbra/shadow/linear_face_shadow.h"

#include "penumbra/geometry/interval.h"

#include <algorithm>
#include <stdexcept>

#include "extended_face.h"
#include "half_plane.h"
#include "penumbra/shadow/contour.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/linear_shadow.h"
#include "penumbra/shadow/shadow_loops.h"
#include "receiver_clip.h"

namespace penumbra {
namespace {

// returns true when the closed segment ab meets the closed solid.
bool segment_meets(const ConvexPolyhedron& solid, const Point3& a, const Point3& b) {
  // Both ends strictly outside one face's plane: the segment misses (the usual case, decided
  // without constructing the line's crossings).
  for (const Face& face : solid.faces())
    if (face.plane.oriented_side(a) == CGAL::ON_POSITIVE_SIDE &&
        face.plane.oriented_side(b) == CGAL::ON_POSITIVE_SIDE)
      return false;
  const auto inside = line_in_solid(solid, a, b);
  return inside && inside->first <= 1 && inside->second >= 0;
}

}  // namespace

SourceOcclusion source_occlusion(const ConvexPolyhedron& solid, const Point3& q1, const Point3& q2,
                                 OpenEnd open) {
  SourceOcclusion result;
  // An occluder with no face turned toward either end point casts nothing, even
  // when the source lies on it (a tube on a ceiling's lower face).
  result.casts = !contour(solid, q1).empty() || !contour(solid, q2).empty();
  if (!result.casts) return result;
  result.touches = segment_meets(solid, q1, q2);
  if (result.touches) return result;
  try {
    result.volumes = linear_volumes(solid, q1, q2, open);
  } catch (const std::domain_error&) {
    result.edge_on = true;
  }
  return result;
}

std::optional<VisibleSource> visible_source(const Face& face, const Point3& q1, const Point3& q2) {
  const Exact f1 = plane_value(face.plane, q1), f2 = plane_value(face.plane, q2);
  if (!CGAL::is_positive(f1) && !CGAL::is_positive(f2)) return std::nullopt;
  VisibleSource source{q1, q2, false};
  if (!CGAL::is_positive(f1) || !CGAL::is_positive(f2)) {
    // Fig. 7, S3: the face's plane cuts the source; only the part on its outer side
    // lights the face. The cut point itself lies in the plane (grazing: no light).
    const Point3 cut = q1 + (f1 / (f1 - f2)) * (q2 - q1);
    (CGAL::is_positive(f1) ? source.q2 : source.q1) = cut;
    source.clipped = true;
    source.open = CGAL::is_positive(f1) ? OpenEnd::q2 : OpenEnd::q1;
  }
  return source;
}

FaceShadow linear_face_shadow(const Face& face, const Point3& q1, const Point3& q2,
                              std::vector<Occluder> occluders) {
  FaceShadow result;
  result.extended = true;
  const auto source = visible_source(face, q1, q2);
  if (!source) {
    // Section 4.1.2 / Fig. 7, S2: invisible from both end points; wholly unlit.
    return detail::unlit_extended(face);
  }
  result.source_clipped = source->clipped;

  const detail::ReceiverClip receiver(face);
  std::vector<Ring2> shadows, umbrae;
  for (const Occluder& occluder : occluders) {
    const ConvexPolyhedron& solid = *occluder.solid;
    // Only the part of V strictly in front of the face's plane can block light.
    if (!detail::reaches_front(solid, face)) continue;
    std::optional<SourceOcclusion> own;
    if (!occluder.whole || source->clipped)
      own = source_occlusion(solid, source->q1, source->q2, source->open);
    const SourceOcclusion& occlusion = own ? *own : *occluder.whole;
    if (!occlusion.casts) continue;
    if (occlusion.touches)
      throw std::domain_error("the linear source touches or passes through an occluder");
    if (occlusion.edge_on)
      throw std::domain_error("an end of the linear source lies in the plane of a flat occluder");
    const auto& volumes = occlusion.volumes;
    const LinearShadowRings rings = detail::clip_by_volumes(*volumes, receiver);
    if (!rings.penumbra) continue;
    OccluderShadow shadow{occluder.id, *rings.penumbra, rings.umbra, volumes->kind};
    shadow.object_space = !projects_onto(solid, face, source->q1, source->q2);
    if (!shadow.object_space) {
      ShadowLoops loops = shadow_loops(solid, face, source->q1, source->q2, *volumes);
      shadow.penumbra_loop = std::move(loops.penumbra_loop);
      shadow.umbra_loop = std::move(loops.umbra_loop);
    }
    shadows.push_back(shadow.polygon);
    if (shadow.umbra) umbrae.push_back(*shadow.umbra);
    result.occluders.push_back(std::move(shadow));
  }

  result.joint_occlusion = detail::any_interiors_overlap(shadows);
  detail::fill_sets(result, shadows, umbrae, face);
  return result;
}

}  // namespace penumbra
