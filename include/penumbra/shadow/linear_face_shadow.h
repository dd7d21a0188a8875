#pragma once
// The shadow map of one face under one linear source (Nishita 1985 sections 4.1.2
// and 4.2, Fig. 7): per occluder its shadow and umbra (and, where the contours
// project onto the face, its raw loops), and over all occluders the exact sets
// shadow (union of the occluders' shadows), umbra (union of umbrae), penumbra =
// shadow - umbra and lit = face - shadow (DESIGN.md, "Conventions").

#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/face_shadow.h"
#include "penumbra/shadow/linear_volumes.h"

namespace penumbra {

// What an occluder does under a whole source q1q2 (the checks and volumes of
// linear_face_shadow). None of it depends on the receiving face unless the face's plane
// cuts the source (Fig. 7, S3), so a scene makes it once per occluder and source.
struct SourceOcclusion {
  bool casts = false;    // some face of the occluder is turned toward an end point
  bool touches = false;  // the closed source meets the closed occluder
  bool edge_on = false;  // an end point lies in the plane of a flat occluder (unsupported)
  std::optional<LinearVolumes> volumes;  // when it casts, does not touch and is not edge-on
};

// returns what solid does under the source q1q2, open at the end `open` (a clipped source's cut
// point: its volumes carry their limits there, linear_volumes.h).
SourceOcclusion source_occlusion(const ConvexPolyhedron& solid, const Point3& q1, const Point3& q2,
                                 OpenEnd open = OpenEnd::none);

struct Occluder {
  std::size_t id;
  const ConvexPolyhedron* solid;
  // source_occlusion(*solid, q1, q2) for the whole source, when known; used for the faces
  // that see all of it.
  const SourceOcclusion* whole = nullptr;
};

// The part of the source a face can see (Fig. 7): q1q2 cut by the face's plane.
struct VisibleSource {
  Point3 q1, q2;
  bool clipped = false;          // the face's plane cuts the source
  OpenEnd open = OpenEnd::none;  // when clipped: the end that is the cut point
};

// returns the part of the source strictly on the face's outer side, closed at the
// cut; nullopt when neither end point is strictly outside (the face is unlit, S2).
std::optional<VisibleSource> visible_source(const Face& face, const Point3& q1, const Point3& q2);

// computes the face's shadow map for the source q1q2 and the occluders (reported
// in the order given). Occluders that cannot reach the face (no
// vertex strictly in front of its plane) are skipped. Throws std::domain_error when
// the visible part of the source touches an occluder that casts a shadow.
FaceShadow linear_face_shadow(const Face& face, const Point3& q1, const Point3& q2,
                              std::vector<Occluder> occluders);

}  // namespace penumbra
