#pragma once
// The penumbra and umbra one convex occluder casts on one face from a linear
// source Q1Q2 (Nishita 1985 section 4.1), by two independent derivations:
//
//  (b) section 4.1.1 in the plane: project the contours C1 from Q1 and C2 from Q2
//      onto the face's plane; umbra = C1' ∩ C2', penumbra = conv(C1' ∪ C2');
//  (c) object space: clip the face by the umbra volume and the penumbra volume of
//      Appendix A2 (linear_volumes.h).
//
// (b) applies only when every vertex of the occluder lies strictly between the
// face's plane and both end points (then every contour vertex projects onto the
// plane); otherwise some side edges of the penumbra volume never reach the plane
// (the object-space case of section 4.2.2) and (c) alone gives the answer. Both
// regions are convex (sections of convex volumes), counter-clockwise in the face's
// frame, in canonical form.

#include <optional>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/shadow/linear_volumes.h"
#include "penumbra/shadow/region.h"

namespace penumbra {

struct LinearShadowRings {
  std::optional<Ring2> penumbra;  // the face ∩ closure of the penumbra volume (shadow of V)
  std::optional<Ring2> umbra;     // the face ∩ closure of the umbra volume
};

// returns true when derivations (a) and (b) apply: every vertex v of solid has
// 0 < F(v) < F(Q_r) for r = 1, 2, where F is the face's plane.
bool projects_onto(const ConvexPolyhedron& solid, const Face& face, const Point3& q1,
                   const Point3& q2);

// derivation (c): clips the face by the closed volumes.
LinearShadowRings clip_by_volumes(const Face& face, const LinearVolumes& volumes);

// derivation (b): hull and intersection of the projected contours, clipped to the
// face. Precondition: projects_onto(solid, face, q1, q2).
LinearShadowRings project_contours(const ConvexPolyhedron& solid, const Face& face,
                                   const Point3& q1, const Point3& q2,
                                   const LinearVolumes& volumes);

// returns the contour projected from q onto the face's plane, in the face's frame,
// in contour order (clockwise seen from q, hence clockwise in the frame).
// Precondition: every contour vertex lies strictly between q and the plane.
Ring2 projected_contour(const ConvexPolyhedron& solid, const std::vector<int>& contour,
                        const Face& face, const Point3& q);

}  // namespace penumbra
