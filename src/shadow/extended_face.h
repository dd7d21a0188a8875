#pragma once
// The steps the face maps of extended sources (linear and area) share (private to the layer):
// which occluders can reach the face, the face that sees none of the source, and the exact
// sets from the occluders' shadows and umbrae.

#include <algorithm>
#include <utility>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/face_shadow.h"
#include "region_set.h"

namespace penumbra::detail {

// returns true when some vertex of solid lies strictly in front of the face's plane: only
// that part of it can block light reaching the face.
inline bool reaches_front(const ConvexPolyhedron& solid, const Face& face) {
  return std::any_of(solid.vertices().begin(), solid.vertices().end(), [&](const Point3& p) {
    return face.plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE;
  });
}

// returns the map of a face that sees none of an extended source: all umbra.
inline FaceShadow unlit_extended(const Face& face) {
  FaceShadow unlit = unlit_face(face);
  unlit.extended = true;
  unlit.umbra = unlit.shadow;
  return unlit;
}

// fills result's shadow, umbra, penumbra and lit from the shadows and umbrae on the face
// (shadow_sets).
inline void fill_sets(FaceShadow& result, const std::vector<Ring2>& shadows,
                      const std::vector<Ring2>& umbrae, const Face& face) {
  ShadowSets sets = shadow_sets(shadows, umbrae, face.ring);
  result.shadow = std::move(sets.shadow);
  result.umbra = std::move(sets.umbra);
  result.penumbra = std::move(sets.penumbra);
  result.lit = std::move(sets.lit);
}

}  // namespace penumbra::detail
