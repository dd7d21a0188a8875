#pragma once
// An exact shadow oracle written independently of the shadow engine: a point X is
// in shadow when the source is not strictly on the outer side of X's face, or when
// the open segment from X to the source (the open ray toward the sun) meets an
// occluder's interior — found by clipping the segment's parameter interval against
// each open half-space of the occluder (Cyrus-Beck), or, for a two-sided polygon,
// when the segment crosses its plane once at a point strictly inside every edge.

#include <variant>

#include "penumbra/scene/scene.h"

namespace penumbra::test {

// returns true when the open segment from x toward light meets occluder's interior.
inline bool segment_blocked(const Point3& x, const Light& light, const ConvexPolyhedron& occluder) {
  // Parameterise Y(t) = x + t D, t in (0, 1) toward a point, t in (0, inf) toward the sun.
  Vector3 direction;
  bool bounded = true;
  if (const auto* point = std::get_if<PointLight>(&light.source)) {
    direction = to_exact(point->position) - x;
  } else {
    direction = -to_exact_vector(std::get<DirectionalLight>(light.source).direction);
    bounded = false;
  }
  if (occluder.is_flat()) {
    const Face& face = occluder.faces().front();
    const Exact at_x =
        face.plane.a() * x.x() + face.plane.b() * x.y() + face.plane.c() * x.z() + face.plane.d();
    const Exact rate = face.plane.orthogonal_vector() * direction;
    if (CGAL::is_zero(rate)) return false;  // parallel: no single crossing
    const Exact t = -at_x / rate;
    if (t <= 0 || (bounded && t >= 1)) return false;
    const Point3 y = x + t * direction;
    const std::size_t n = face.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vector3 edge = face.vertices[(k + 1) % n] - face.vertices[k];
      if (CGAL::cross_product(edge, y - face.vertices[k]) * face.plane.orthogonal_vector() <= 0)
        return false;
    }
    return true;
  }
  bool has_high = bounded;
  Exact low = 0, high = 1;
  for (const Face& face : occluder.faces()) {
    // f(t) = f(x) + t (n . D) < 0
    const Exact at_x =
        face.plane.a() * x.x() + face.plane.b() * x.y() + face.plane.c() * x.z() + face.plane.d();
    const Exact rate = face.plane.orthogonal_vector() * direction;
    if (CGAL::is_zero(rate)) {
      if (at_x >= 0) return false;
      continue;
    }
    const Exact crossing = -at_x / rate;
    if (rate > 0) {
      if (!has_high || crossing < high) high = crossing;
      has_high = true;
    } else if (crossing > low) {
      low = crossing;
    }
    if (has_high && low >= high) return false;
  }
  return !has_high || low < high;
}

// returns true when the source is strictly on the outer side of the face's plane,
// decided from three of its vertices (orientation of the tetrahedron), not its plane.
inline bool faces_light(const Face& face, const Light& light) {
  const Point3& a = face.vertices[0];
  const Point3& b = face.vertices[1];
  const Point3& c = face.vertices[2];
  const Vector3 normal = CGAL::cross_product(b - a, c - b);  // counter-clockwise from outside
  if (const auto* point = std::get_if<PointLight>(&light.source))
    return normal * (to_exact(point->position) - a) > 0;
  return normal * to_exact_vector(std::get<DirectionalLight>(light.source).direction) < 0;
}

// returns true when x, a point of face, is in shadow.
// The receiver itself is not skipped: a convex solid cannot block its own lit face.
inline bool oracle_in_shadow(const Scene& scene, const Face& face, const Point3& x,
                             const Light& light) {
  if (!faces_light(face, light)) return true;
  for (const Object& object : scene.objects)
    if (segment_blocked(x, light, object.solid)) return true;
  return false;
}

}  // namespace penumbra::test
