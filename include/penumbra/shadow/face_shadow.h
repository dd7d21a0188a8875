#pragma once
// The shadow map of one face under one point or directional source (Nishita 1985
// section 3.2: "the shadow areas on the face are obtained by the union of the
// shadows cast on it"): the exact union of the occluders' convex shadow polygons,
// and its complement in the face. For these sources umbra = shadow and the
// penumbra is empty (DESIGN.md, "Conventions").

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/linear_volumes.h"
#include "penumbra/shadow/region.h"

namespace penumbra {

class ExactUmbra;

struct OccluderShadow {
  std::size_t occluder;  // the occluding object's index (in the caller's numbering)
  Ring2 polygon;         // convex, counter-clockwise, canonical, in the face's frame; for a
                         // linear source the occluder's whole shadow (penumbra and umbra)
  // Linear and area sources only (Nishita 1985 section 4.1, docs/linear-shadows.md,
  // docs/area-sources.md):
  std::optional<Ring2> umbra{};  // convex, inside polygon
  // Linear sources only:
  std::optional<LinearCase> linear_case{};  // App. A2 Case A or B
  bool object_space = false;                // the contours do not project onto the face: no loops
  Ring2 penumbra_loop{};                    // raw loops, clockwise, as built (section 4.1.2)
  Ring2 umbra_loop{};                       // may cross itself
};

struct FaceShadow {
  bool faces_away = false;      // the source is not strictly on the face's outer side
  bool beyond_range = false;    // the face lies wholly outside the sphere of lighting: not computed
  bool extended = false;        // computed for a linear or area source: umbra, penumbra apply
  bool source_clipped = false;  // extended: the face's plane cuts the source (Fig. 7, S3)
  bool joint_occlusion = false;  // extended: two occluders' penumbrae overlap
  // linear, with ShadowOptions::joint_umbrae: joint_occlusion then says that the umbra has
  // joint parts, and this holds the exact umbra and penumbra with them and their conic edges
  // (exact_umbra.h); umbra and penumbra below stay the straight sets of single occluders.
  std::shared_ptr<const ExactUmbra> curved;
  std::vector<OccluderShadow> occluders;  // sorted by occluder
  Region2 shadow;                         // = umbra for point and directional sources
  Region2 umbra;                          // extended: union of the occluders' umbrae
  Region2 penumbra;                       // extended: shadow - umbra
  Region2 lit;                            // the face minus shadow
  // beyond_range with ShadowOptions::occluders_beyond_range: every object that may shadow
  // the face (a superset, increasing); the regions above are then not computed.
  std::vector<std::size_t> possible_occluders;
};

// returns the face's polygon in its own frame (counter-clockwise).
Ring2 face_ring(const Face& face);

// returns the face as a region of its own frame: convex_region(face_ring(face)), from the
// ring and area the face keeps.
Region2 face_region(const Face& face);

// returns the shadow map of a face that faces away from the source: all shadow.
FaceShadow unlit_face(const Face& face);

// unites the occluders' shadow polygons on face (Polygon_set_2, aggregated join)
// and subtracts the union from the face, unless lit is false (FaceShadow::lit is then left
// empty). occluders must be sorted by occluder.
FaceShadow unite_shadows(const Face& face, std::vector<OccluderShadow> occluders, bool lit = true);

}  // namespace penumbra
