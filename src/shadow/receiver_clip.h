#pragma once
// A receiving face prepared once for clipping by many shadow volumes (Nishita 1985
// section 3.2: the section of a volume by the face's plane, clipped to the face).
//
// The clip of half_plane.h, done so that exact numbers are made only where needed:
// each sign is taken from interval arithmetic when the interval decides it (then
// it is the exact sign), and otherwise computed in rationals (a vertex exactly on a
// trace is the usual case). Each vertex remembers the two lines it lies on (a face
// edge or a volume plane's trace), so the exact vertices are the crossings of those
// lines, solved once in rationals instead of through the chain of lazy clips that
// would otherwise build them; the points are the same rationals either way, so the
// result is exactly the one of clip(). No epsilon decides anything.

#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/interval.h"
#include "penumbra/shadow/linear_shadow.h"
#include "penumbra/shadow/linear_volumes.h"
#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns a . b over three coordinates, skipping the products with a zero factor: the planes
// and frames of axis-aligned faces (the usual case in CAD) are mostly zeros, and each
// rational product costs a gcd. The same value.
template <class A, class B>
Exact::ET sparse_dot(const A& a, const B& b) {
  Exact::ET sum;
  for (int i = 0; i < 3; ++i)
    if (!CGAL::is_zero(a[i]) && !CGAL::is_zero(b[i])) sum += a[i] * b[i];
  return sum;
}

class ReceiverClip {
 public:
  // prepares face: its ring and frame, exact and in intervals.
  explicit ReceiverClip(const Face& face);

  const Face& face() const { return *face_; }

  // returns the face's ring (face_ring), counter-clockwise, as exact points.
  const Ring2& ring() const { return ring_; }

  // returns ring_with_area of the face's ring clipped by the closed half-planes
  // plane(X) <= 0 of volume, in order: the same points as clip() of
  // half_plane.h would give, each known exactly (no lazy construction behind it). A plane
  // parallel to the face keeps all of it or nothing, as there; nothing when it holds the face
  // (its trace is constant 0), unless limits stand in for it (linear_volumes.h: a plane
  // through an open end of the source), and then the face is clipped by those instead.
  std::optional<Ring2> clip(const std::vector<Plane3>& volume,
                            const std::vector<PlaneLimit>& limits = {}) const;

  using Rational = Exact::ET;
  struct Line {  // a s + b t + c = 0 in frame coordinates
    Rational a, b, c;
  };

 private:
  Line trace(const Plane3& plane) const;

  const Face* face_;
  Ring2 ring_;
  std::vector<Line> edges_;  // edges_[k] through ring_[k] and ring_[k + 1]
  Rational origin_[3], u_[3], v_[3];
  std::vector<Interval> s_, t_;  // ring_ in intervals
  Interval origin_box_[3], u_box_[3], v_box_[3];
};

// returns shadow_polygon(occluder, volume, receiver.face()) (shadow_polygon.h).
std::optional<Ring2> shadow_polygon(const ConvexPolyhedron& occluder,
                                    const std::vector<Plane3>& volume,
                                    const ReceiverClip& receiver);

// returns clip_by_volumes(receiver.face(), volumes) (linear_shadow.h).
LinearShadowRings clip_by_volumes(const LinearVolumes& volumes, const ReceiverClip& receiver);

}  // namespace penumbra::detail
