#pragma once
// The shadow map of a face of a mesh part from those of its convex pieces (docs/shadows.md,
// "Faces of real models"): each piece's regions, occluder polygons and loops are carried
// exactly from the piece's frame into the face's (an affine map with rational
// coefficients: both frames lie in the face's plane), and the regions are united.

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "penumbra/geometry/face_frame.h"
#include "penumbra/scene/scene.h"
#include "penumbra/shadow/exact_umbra.h"
#include "penumbra/shadow/face_shadow.h"

namespace penumbra::detail {

// The exact affine map between two frames of one plane: frame coordinates in from to frame
// coordinates in to.
class FrameMap {
 public:
  FrameMap(const FaceFrame& from, const FaceFrame& to);
  Point2 operator()(const Point2& p) const;
  Ring2 ring(const Ring2& ring) const;          // mapped point by point (not made canonical)
  Region2 region(const Region2& region) const;  // mapped and made canonical

 private:
  Rational s0_, su_, sv_, t0_, tu_, tv_;  // s' = s0 + su s + sv t, t' = t0 + tu s + tv t
};

// returns the shadow map of a face made of pieces: for each piece its shadow map and its
// face's frame; frame is the face's. Flags are the pieces' (faces_away, beyond_range: all
// of them; the others: any); occluders follow the pieces' order, each piece's in its own.
// whole, when given, is the face's region: a set that every piece has whole (a face wholly
// lit, or wholly in shadow) is then taken as it, without a Boolean union. lit false: the
// pieces' lit parts were not computed (ShadowOptions::lit_parts); the result's stays empty.
FaceShadow unite_pieces(const std::vector<std::pair<const FaceShadow*, const FaceFrame*>>& pieces,
                        const FaceFrame& frame, const std::optional<Region2>& whole = {},
                        bool lit = true);

// The exact umbra of the tube q1q2 (ends in lexicographic order) on a mesh face of several
// pieces whose pieces have joint parts (exact_umbra.h, issue #17): computed on the whole face
// (its pieces carried into its frame, its outer ring and holes), so that joint parts across
// the pieces' seams are one curved region. united is the face's shadow map from
// unite_pieces: each occluder's shadow and umbra become the convex hulls of its pieces'
// rings, which agree with its whole shadow and single umbra on the face.
std::shared_ptr<const ExactUmbra> mesh_face_umbra(const Scene& scene, const MeshFace& face,
                                                  const std::vector<const Face*>& pieces,
                                                  const FaceShadow& united, const Point3& q1,
                                                  const Point3& q2);

}  // namespace penumbra::detail
