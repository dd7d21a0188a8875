#include "penumbra/shadow/linear_shadow.h"

#include "penumbra/geometry/interval.h"

#include <algorithm>

#include "../geometry/convex_hull_2.h"
#include "half_plane.h"
#include "penumbra/shadow/face_shadow.h"

namespace penumbra {
namespace {

std::optional<Ring2> clip_face(const Face& face, const OpenVolume& volume) {
  if (volume.planes.empty()) return std::nullopt;
  Ring2 ring = face_ring(face);
  for (const Plane3& plane : volume.planes) {
    ring = detail::clip(ring, detail::restrict_to(plane, face.frame));
    if (ring.size() < 3) return std::nullopt;
  }
  return detail::ring_with_area(ring);
}

Ring2 counter_clockwise(Ring2 ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

}  // namespace

bool projects_onto(const ConvexPolyhedron& solid, const Face& face, const Point3& q1,
                   const Point3& q2) {
  const Exact f1 = plane_value(face.plane, q1), f2 = plane_value(face.plane, q2);
  return std::all_of(solid.vertices().begin(), solid.vertices().end(), [&](const Point3& v) {
    const Exact f = plane_value(face.plane, v);
    return CGAL::is_positive(f) && f < f1 && f < f2;
  });
}

LinearShadowRings clip_by_volumes(const Face& face, const LinearVolumes& volumes) {
  return {clip_face(face, volumes.penumbra), clip_face(face, volumes.umbra)};
}

Ring2 projected_contour(const ConvexPolyhedron& solid, const std::vector<int>& contour,
                        const Face& face, const Point3& q) {
  Ring2 ring;
  const Exact fq = plane_value(face.plane, q);
  for (int id : contour) {
    // X = Q + t (v - Q) with F(X) = 0: t = F(Q) / (F(Q) - F(v)).
    const Point3& v = solid.vertices()[id];
    const Exact t = fq / (fq - plane_value(face.plane, v));
    ring.push_back(face.frame.to_frame(q + t * (v - q)));
  }
  return ring;
}

LinearShadowRings project_contours(const ConvexPolyhedron& solid, const Face& face,
                                   const Point3& q1, const Point3& q2,
                                   const LinearVolumes& volumes) {
  // Section 4.1.1: "the intersection of the polygonal area defined by C1' and C2'
  // makes an umbra area ... the minimum convex polygon surrounding C1' and C2'
  // forms a penumbra area". The contours run clockwise; the frame's order is
  // counter-clockwise, so each projected contour is reversed.
  // canonical_ring drops vertices that project onto one another or onto a line.
  const Ring2 c1 =
      canonical_ring(counter_clockwise(projected_contour(solid, volumes.contour1, face, q1)));
  const Ring2 c2 =
      canonical_ring(counter_clockwise(projected_contour(solid, volumes.contour2, face, q2)));
  Ring2 both = c1;
  both.insert(both.end(), c2.begin(), c2.end());
  Ring2 hull;
  for (int index : detail::convex_hull_2(both)) hull.push_back(both[index]);
  const Ring2 window = face_ring(face);
  return {detail::ring_with_area(detail::clip_to_convex(hull, window)),
          detail::ring_with_area(detail::clip_to_convex(detail::clip_to_convex(c1, c2), window))};
}

}  // namespace penumbra
