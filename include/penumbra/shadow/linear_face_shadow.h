#pragma once
// The shadow map of one face under one linear source (Nishita 1985 sections 4.1.2
// and 4.2, Fig. 7): per occluder its penumbra and umbra (and, where the contours
// project onto the face, its raw loops), and over all occluders the exact sets
// shadow (union of penumbrae), umbra (union of umbrae), penumbra = shadow - umbra
// and lit = face - shadow (DESIGN.md, "Conventions").

#include <cstddef>
#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/linear_volumes.h"
#include "penumbra/shadow/region.h"

namespace penumbra {

struct LinearOccluderShadow {
  std::size_t occluder;         // the occluding object's index (the caller's numbering)
  LinearCase kind;              // App. A2 Case A or B
  bool object_space = false;    // the contours do not project onto the face: loops absent
  Ring2 penumbra;               // convex, counter-clockwise, canonical, in the face's frame
  std::optional<Ring2> umbra;   // convex, inside penumbra
  Ring2 penumbra_loop;          // raw loops, clockwise, as built (section 4.1.2)
  Ring2 umbra_loop;             // may cross itself
};

struct LinearFaceShadow {
  bool faces_away = false;       // neither end point strictly on the outer side: all unlit
  bool source_clipped = false;   // the face's plane cuts the source (Fig. 7, S3)
  Point3 q1, q2;                 // the part of the source the face can see
  bool joint_occlusion = false;  // two occluders' penumbrae overlap: the true umbra may be larger
  std::vector<LinearOccluderShadow> occluders;  // sorted by occluder
  Region2 shadow, umbra, penumbra, lit;
};

struct Occluder {
  std::size_t id;
  const ConvexPolyhedron* solid;
};

// computes the face's shadow map for the source q1q2 and the occluders (in any
// order; the result is sorted by id). Occluders that cannot reach the face (no
// vertex strictly in front of its plane) are skipped. Throws InputError-free
// std::invalid_argument when the visible part of the source meets an occluder.
LinearFaceShadow linear_face_shadow(const Face& face, const Point3& q1, const Point3& q2,
                                    std::vector<Occluder> occluders);

}  // namespace penumbra
