#include "penumbra/shadow/shadow_polygon.h"

#include <vector>

#include "half_plane.h"

namespace penumbra {

using detail::HalfPlane;
using detail::restrict_to;

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
    ring = detail::clip(ring, half);
    if (ring.size() < 3) return std::nullopt;
  }
  Ring2 canonical = canonical_ring(ring);
  if (canonical.empty() || !CGAL::is_positive(signed_area(canonical))) return std::nullopt;
  return canonical;
}

}  // namespace penumbra
