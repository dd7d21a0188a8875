#include "penumbra/shadow/linear_shadow.h"

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"

#include <algorithm>

#include "../geometry/convex_hull_2.h"
#include "half_plane.h"
#include "penumbra/shadow/face_shadow.h"
#include "receiver_clip.h"

namespace penumbra {
namespace {

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

namespace detail {

LinearShadowRings clip_by_volumes(const LinearVolumes& volumes, const ReceiverClip& receiver) {
  const auto clip = [&](const OpenVolume& volume) -> std::optional<Ring2> {
    if (volume.planes.empty()) return std::nullopt;
    return receiver.clip(volume.planes, volume.limits);
  };
  return {clip(volumes.penumbra), clip(volumes.umbra)};
}

}  // namespace detail

LinearShadowRings clip_by_volumes(const Face& face, const LinearVolumes& volumes) {
  return detail::clip_by_volumes(volumes, detail::ReceiverClip(face));
}

Ring2 projected_contour(const ConvexPolyhedron& solid, const std::vector<int>& contour,
                        const Face& face, const Point3& q) {
  // X = Q + t (v - Q) with F(X) = 0: t = F(Q) / (F(Q) - F(v)); its frame coordinates are
  // ((Q - O).u + t (v - Q).u) / u.u and the same along v. In rationals (sparse_dot,
  // receiver_clip.h): the points are exact, with no lazy construction behind them.
  using detail::sparse_dot;
  const RationalPlane3& plane = exact_value(face.plane);
  const RationalPoint3& from = exact_value(q);
  const RationalVector3& u = exact_value(face.frame.u());
  const RationalVector3& v = exact_value(face.frame.v());
  const Rational& uu = exact_value(face.frame.squared_u());
  const Rational& vv = exact_value(face.frame.squared_v());
  const RationalVector3 normal = plane.orthogonal_vector();
  const RationalVector3 offset = from - exact_value(face.frame.origin());
  const Rational fq = sparse_dot(from - CGAL::ORIGIN, normal) + plane.d();
  const Rational su = sparse_dot(offset, u), sv = sparse_dot(offset, v);
  Ring2 ring;
  for (int id : contour) {
    const RationalVector3 w = exact_value(solid.vertices()[id]) - from;
    // F(v) - F(Q) = n.(v - Q).
    const Rational t = -fq / sparse_dot(w, normal);
    ring.push_back(from_exact<Point2>(
        RationalPoint2((su + t * sparse_dot(w, u)) / uu, (sv + t * sparse_dot(w, v)) / vv)));
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
