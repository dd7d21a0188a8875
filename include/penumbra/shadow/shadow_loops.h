#pragma once
// Penumbra and umbra loops on a face (Nishita 1985 section 4.1.2), derivation (a):
// the contours C1 and C2 projected onto the face from Q1 and Q2; in Case A each is
// split at P_L and P_R into two strings; the penumbra loop joins the strings on the
// penumbra volume (C1' from P_L to P_R, then C2' from P_R to P_L) and is convex; the
// umbra loop joins the other two and may twist. The umbra is what the umbra loop
// surrounds clockwise; what it surrounds counter-clockwise belongs to the penumbra.
// In Case B the nearer end point's projected contour is the penumbra loop and the
// other the umbra loop.

#include <vector>

#include "penumbra/shadow/linear_shadow.h"

namespace penumbra {

struct ShadowLoops {
  Ring2 penumbra_loop;  // in the face's frame, in contour order (clockwise), as built
  Ring2 umbra_loop;     // may cross itself
};

// builds the loops. Precondition: projects_onto(solid, face, q1, q2).
ShadowLoops shadow_loops(const ConvexPolyhedron& solid, const Face& face, const Point3& q1,
                         const Point3& q2, const LinearVolumes& volumes);

// returns the regions a closed loop surrounds clockwise (winding number -1), each
// a canonical counter-clockwise ring: the faces of the loop's exact arrangement
// (CGAL Arrangement_2) whose winding number is -1.
std::vector<Ring2> clockwise_regions(const Ring2& loop);

// derivation (a): the clockwise regions of both loops, clipped to the face. A
// region made of several arrangement faces is reported as nullopt penumbra/umbra
// only if it cannot be one convex ring (never for a single convex occluder).
LinearShadowRings loop_regions(const Face& face, const ShadowLoops& loops);

}  // namespace penumbra
