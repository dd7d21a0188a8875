#include "penumbra/shadow/linear_face_shadow.h"

#include <algorithm>
#include <stdexcept>

#include "half_plane.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/linear_shadow.h"
#include "penumbra/shadow/shadow_loops.h"
#include "region_set.h"

namespace penumbra {
namespace {

Exact plane_value(const Plane3& plane, const Point3& p) {
  return plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d();
}

// returns true when the closed segment ab meets the closed solid.
bool segment_meets(const ConvexPolyhedron& solid, const Point3& a, const Point3& b) {
  Exact low = 0, high = 1;
  for (const Face& face : solid.faces()) {
    const Exact fa = plane_value(face.plane, a), fb = plane_value(face.plane, b);
    // f(t) = fa + t (fb - fa) <= 0
    if (fa == fb) {
      if (CGAL::is_positive(fa)) return false;
      continue;
    }
    const Exact t = fa / (fa - fb);
    if (fb > fa) high = CGAL::min(high, t);
    else low = CGAL::max(low, t);
    if (low > high) return false;
  }
  return true;
}

}  // namespace

LinearFaceShadow linear_face_shadow(const Face& face, const Point3& q1, const Point3& q2,
                                    std::vector<Occluder> occluders) {
  LinearFaceShadow result;
  const Ring2 ring = face_ring(face);
  const Exact f1 = plane_value(face.plane, q1), f2 = plane_value(face.plane, q2);
  if (!CGAL::is_positive(f1) && !CGAL::is_positive(f2)) {
    // Section 4.1.2 / Fig. 7, S2: invisible from both end points; wholly unlit.
    result.faces_away = true;
    result.q1 = q1;
    result.q2 = q2;
    result.shadow = result.umbra = convex_region(ring);
    return result;
  }
  // Fig. 7, S3: the face's plane cuts the source; only the part on its outer side
  // lights the face. The cut point itself lies in the plane (grazing: no light).
  result.q1 = q1;
  result.q2 = q2;
  if (!CGAL::is_positive(f1) || !CGAL::is_positive(f2)) {
    const Point3 cut = q1 + (f1 / (f1 - f2)) * (q2 - q1);
    (CGAL::is_positive(f1) ? result.q2 : result.q1) = cut;
    result.source_clipped = true;
  }

  std::sort(occluders.begin(), occluders.end(),
            [](const Occluder& a, const Occluder& b) { return a.id < b.id; });
  std::vector<Ring2> penumbrae, umbrae;
  for (const Occluder& occluder : occluders) {
    const ConvexPolyhedron& solid = *occluder.solid;
    // Only the part of V strictly in front of the face's plane can block light.
    if (std::none_of(solid.vertices().begin(), solid.vertices().end(), [&](const Point3& p) {
          return face.plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE;
        }))
      continue;
    if (segment_meets(solid, result.q1, result.q2))
      throw std::domain_error("the linear source touches or passes through an occluder");
    const auto volumes = linear_volumes(solid, result.q1, result.q2);
    if (!volumes) continue;
    const LinearShadowRings rings = clip_by_volumes(face, *volumes);
    if (!rings.penumbra) continue;
    LinearOccluderShadow shadow;
    shadow.occluder = occluder.id;
    shadow.kind = volumes->kind;
    shadow.penumbra = *rings.penumbra;
    shadow.umbra = rings.umbra;
    shadow.object_space = !projects_onto(solid, face, result.q1, result.q2);
    if (!shadow.object_space) {
      ShadowLoops loops = shadow_loops(solid, face, result.q1, result.q2, *volumes);
      shadow.penumbra_loop = std::move(loops.penumbra_loop);
      shadow.umbra_loop = std::move(loops.umbra_loop);
    }
    penumbrae.push_back(shadow.penumbra);
    if (shadow.umbra) umbrae.push_back(*shadow.umbra);
    result.occluders.push_back(std::move(shadow));
  }

  for (std::size_t i = 0; i < penumbrae.size() && !result.joint_occlusion; ++i)
    for (std::size_t j = i + 1; j < penumbrae.size() && !result.joint_occlusion; ++j)
      result.joint_occlusion = detail::interiors_overlap(penumbrae[i], penumbrae[j]);
  result.shadow = detail::unite_minus(penumbrae);
  result.umbra = detail::unite_minus(umbrae);
  result.penumbra = detail::unite_minus(penumbrae, umbrae);
  result.lit = detail::unite_minus({ring}, penumbrae);
  return result;
}

}  // namespace penumbra
