#pragma once
// The shadow map of one face under one area source (docs/area-sources.md): per occluder its
// shadow (the face ∩ the penumbra volume of area_volumes.h) and umbra, and over all occluders
// the exact sets shadow (union of the shadows), umbra (union of the single occluders'
// umbrae, and for a one-sided source the part of the face behind the source's plane),
// penumbra = shadow - umbra and lit = face - shadow (DESIGN.md, "Conventions").

#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/area_volumes.h"
#include "penumbra/shadow/face_shadow.h"

namespace penumbra {

// What an occluder does under an area source.
struct AreaOcclusion {
  bool touches = false;                // the closed source meets the closed occluder
  std::optional<AreaVolumes> volumes;  // when it casts and does not touch
};

// returns what solid does under the source (vertices in cycle order, no three on a line).
AreaOcclusion area_occlusion(const ConvexPolyhedron& solid, const std::vector<Point3>& source);

// An occluder of an area source, with what it does under the whole source when known (it
// serves every face whose plane does not cut the source).
struct AreaOccluder {
  std::size_t id;
  const ConvexPolyhedron* solid;
  const AreaOcclusion* whole = nullptr;
};

// returns the part of the source face (a convex face, its ring in its own frame) strictly on
// the positive side of plane, closed at the cut, as world points in cycle order; empty when
// that part has no area.
std::vector<Point3> source_part(const Face& source, const Plane3& plane);

// computes the face's shadow map for the area source whose emitting side is the face
// `source` of a flat polygon (two_sided: both sides emit), for the occluders (reported in
// the order given). Occluders with no vertex strictly in front of the face are skipped.
// Throws std::domain_error when the visible part of the source touches an occluder that
// casts a shadow.
FaceShadow area_face_shadow(const Face& face, const Face& source, bool two_sided,
                            const std::vector<AreaOccluder>& occluders);

}  // namespace penumbra
