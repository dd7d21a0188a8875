#include "half_plane.h"

#include "penumbra/geometry/interval.h"

#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"

namespace penumbra::detail {

HalfPlane restrict_to(const Plane3& plane, const FaceFrame& frame) {
  const Vector3 normal = plane.orthogonal_vector();
  const Point3& o = frame.origin();
  return {normal * frame.u(), normal * frame.v(), plane_value(plane, o)};
}

Ring2 clip(const Ring2& ring, const HalfPlane& half) {
  if (CGAL::is_zero(half.a) && CGAL::is_zero(half.b))
    return CGAL::is_negative(half.c) ? ring : Ring2{};
  Ring2 out;
  const std::size_t n = ring.size();
  std::vector<Exact> value(n);
  std::vector<CGAL::Sign> sign(n);
  for (std::size_t k = 0; k < n; ++k) {
    value[k] = half.a * ring[k].x() + half.b * ring[k].y() + half.c;
    sign[k] = CGAL::sign(value[k]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    if (sign[k] != CGAL::POSITIVE) out.push_back(ring[k]);
    if (sign[k] * sign[next] == CGAL::NEGATIVE) {
      const Exact t = value[k] / (value[k] - value[next]);
      out.emplace_back(ring[k].x() + t * (ring[next].x() - ring[k].x()),
                       ring[k].y() + t * (ring[next].y() - ring[k].y()));
    }
  }
  return out;
}

std::optional<Ring2> ring_with_area(const Ring2& ring) {
  Ring2 canonical = canonical_ring(ring);
  if (canonical.empty() || area_sign(canonical) != CGAL::POSITIVE) return std::nullopt;
  return canonical;
}

Ring2 clip_to_convex(Ring2 ring, const Ring2& window) {
  const std::size_t n = window.size();
  for (std::size_t k = 0; k < n && ring.size() >= 3; ++k) {
    // Inside is to the left of the window's edge p -> q.
    const Point2& p = window[k];
    const Point2& q = window[(k + 1) % n];
    const Exact a = q.y() - p.y(), b = p.x() - q.x();
    ring = clip(ring, {a, b, -(a * p.x() + b * p.y())});
  }
  return ring;
}

}  // namespace penumbra::detail
