#pragma once
// The broad phase of shadow detection (Nishita 1985 section 3.2, last paragraph:
// reduce the pairs tested): an occluder can shadow a face only if it meets the
// region swept by the segments from the face to the source, conv(face, source) —
// the prism toward the sun, cut where it leaves the scene's bounding box. Boxes
// around those regions and around the objects are intersected with CGAL's
// box_intersection_d. Every box is rounded outward, so no pair that can interact
// is dropped.

#include <cstddef>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/visibility/light_position.h"

namespace penumbra {

struct Receiver {
  std::size_t object;  // index into the objects given to the broad phase
  std::size_t face;    // index into that object's faces()
};

// returns, for each receiver, the sorted indices of the objects (other than the
// receiver's own) whose bounding box meets the bounding box of the receiver's
// region toward light.
std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const LightPosition& light);

// returns the candidates for a linear source q1q2: the region swept by the segments
// from the face to the source is conv(face, q1, q2).
std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const Point3& q1, const Point3& q2);

}  // namespace penumbra
