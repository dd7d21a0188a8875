#include "penumbra/shadow/shadow_polygon.h"

#include <vector>

namespace penumbra {
namespace {

// An open half-plane A s + B t + C < 0 of a face's frame coordinates (s, t): the
// section of an open half-space of space by the face's plane.
struct HalfPlane {
  Exact a, b, c;
};

// restricts the open half-space plane(X) < 0 to the face's plane, X = o + s u + t v.
HalfPlane restrict_to(const Plane3& plane, const FaceFrame& frame) {
  const Vector3 normal = plane.orthogonal_vector();
  return {normal * frame.u(), normal * frame.v(),
          plane.a() * frame.origin().x() + plane.b() * frame.origin().y() +
              plane.c() * frame.origin().z() + plane.d()};
}

// clips a convex ring to the closed half-plane (Sutherland-Hodgman, exact). A
// half-plane parallel to the face (a = b = 0) is constant on it: the open
// condition c < 0 keeps everything or nothing (the tie-break that makes an
// occluder lying flat behind the face's plane cast no shadow).
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

}  // namespace

bool faces_away(const Face& face, const LightPosition& light) {
  return light.side_of(face.plane) != CGAL::POSITIVE;
}

std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder, const Face& receiver,
                                    const LightPosition& light) {
  // Only the part of V strictly in front of the face's plane can block a segment
  // from the face to the source (docs/shadows.md, "the slab"): quick rejection.
  bool in_front = false;
  for (const Point3& p : occluder.vertices())
    if (receiver.plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE) {
      in_front = true;
      break;
    }
  if (!in_front) return std::nullopt;

  const std::vector<Face>& faces = occluder.faces();
  std::vector<CGAL::Sign> side(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) side[f] = light.side_of(faces[f].plane);

  // The open shadow volume is the intersection of open half-spaces (section 3.2):
  // (1) beyond each face turned toward the source (F > 0 at the source), and
  //     inside each face whose plane holds the source (F = 0): plane(X) < 0;
  // (2) inside the pyramid from the source through each contour edge, the edges
  //     between a face turned toward the source and one that is not.
  std::vector<HalfPlane> halves;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (side[f] == CGAL::NEGATIVE) continue;
    halves.push_back(restrict_to(faces[f].plane, receiver.frame));
    if (side[f] == CGAL::ZERO) continue;
    const Face& face = faces[f];
    const std::size_t n = face.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (side[face.neighbours[k]] == CGAL::POSITIVE) continue;
      // The face's next vertex is off the contour plane: the source is strictly
      // off this face's plane.
      const auto contour = light.plane_through(face.vertices[k], face.vertices[(k + 1) % n],
                                               face.vertices[(k + 2) % n]);
      if (contour) halves.push_back(restrict_to(*contour, receiver.frame));
    }
  }

  Ring2 ring;
  for (const Point3& p : receiver.vertices) ring.push_back(receiver.frame.to_frame(p));
  for (const HalfPlane& half : halves) {
    ring = clip(ring, half);
    if (ring.size() < 3) return std::nullopt;
  }
  Ring2 canonical = canonical_ring(ring);
  if (canonical.empty() || !CGAL::is_positive(signed_area(canonical))) return std::nullopt;
  return canonical;
}

}  // namespace penumbra
