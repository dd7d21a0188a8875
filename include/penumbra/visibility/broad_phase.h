#pragma once
// The broad phase of shadow detection (Nishita 1985 section 3.2, last paragraph:
// reduce the pairs tested): an occluder can shadow a face only if it meets the
// region swept by the segments from the face to the source, conv(face, source) —
// the prism toward the sun (visibility/swept_region.h). A bounding volume hierarchy
// over the objects' boxes (rounded outward) is walked with each face's region, leaving
// the boxes and then the objects that a supporting plane of the region certainly
// separates (interval arithmetic): no pair that can interact is dropped, and a model of
// 10^5 faces is queried in O(log n) boxes per face rather than tested pair by pair.

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
// receiver's own) that no plane certainly separates from the receiver's region toward
// light.
std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const LightPosition& light);

// returns the candidates for a linear source q1q2: the region swept by the segments
// from the face to the source is conv(face, q1, q2).
std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const Point3& q1, const Point3& q2);

// returns the candidates for a convex polygon source (its vertices in cycle order, no three
// on a line): the region swept is conv(face, source).
std::vector<std::vector<std::size_t>> candidate_occluders(
    const std::vector<const ConvexPolyhedron*>& objects, const std::vector<Receiver>& receivers,
    const std::vector<Point3>& source);

}  // namespace penumbra
