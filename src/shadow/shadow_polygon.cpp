#include "penumbra/shadow/shadow_polygon.h"

#include <algorithm>
#include <vector>

#include "receiver_clip.h"

namespace penumbra {

bool faces_away(const Face& face, const LightPosition& light) {
  return light.side_of(face.plane) != CGAL::POSITIVE;
}

std::vector<Plane3> shadow_volume(const ConvexPolyhedron& occluder, const LightPosition& light) {
  const std::vector<Face>& faces = occluder.faces();
  std::vector<CGAL::Sign> side(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) side[f] = light.side_of(faces[f].plane);

  // The open shadow volume is the intersection of open half-spaces (section 3.2):
  // (1) beyond each face turned toward the source (F > 0 at the source), and
  //     inside each face whose plane holds the source (F = 0): plane(X) < 0;
  // (2) inside the pyramid from the source through each contour edge, the edges
  //     between a face turned toward the source and one that is not.
  std::vector<Plane3> planes;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (side[f] == CGAL::NEGATIVE) continue;
    planes.push_back(faces[f].plane);
    if (side[f] == CGAL::ZERO) continue;
    const Face& face = faces[f];
    const std::size_t n = face.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (side[face.neighbours[k]] == CGAL::POSITIVE) continue;
      // The face's next vertex is off the contour plane: the source is strictly
      // off this face's plane.
      const auto contour = light.plane_through(face.vertices[k], face.vertices[(k + 1) % n],
                                               face.vertices[(k + 2) % n]);
      if (contour) planes.push_back(*contour);
    }
  }
  return planes;
}

namespace detail {

std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder,
                                    const std::vector<Plane3>& volume,
                                    const ReceiverClip& receiver) {
  // Only the part of V strictly in front of the face's plane can block a segment
  // from the face to the source (docs/shadows.md, "the slab"): quick rejection.
  const Plane3& plane = receiver.face().plane;
  if (std::none_of(occluder.vertices().begin(), occluder.vertices().end(), [&](const Point3& p) {
        return plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE;
      }))
    return std::nullopt;
  return receiver.clip(volume);
}

}  // namespace detail

std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder,
                                    const std::vector<Plane3>& volume, const Face& receiver) {
  return detail::shadow_polygon(occluder, volume, detail::ReceiverClip(receiver));
}

std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder, const Face& receiver,
                                    const LightPosition& light) {
  return shadow_polygon(occluder, shadow_volume(occluder, light), receiver);
}

}  // namespace penumbra
