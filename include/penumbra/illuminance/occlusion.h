#pragma once
// Exact occlusion for illuminance: which part of a source a receiving point sees
// (Nishita 1985 section 4.2.3). Every decision here is exact (Epeck); the only
// doubles are the coordinates given, each taken as the rational it is.
//
// "Hidden" means: the OPEN segment from the apex to X meets the occluder's interior
// (a flat polygon's relative interior). So a segment that only touches the occluder's
// boundary, or grazes a face, is not blocked, and a lamp sitting on a face lights
// everything on the outer side of that face (docs/illuminance.md, "Occlusion").

#include <optional>
#include <vector>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/interval.h"
#include "penumbra/shadow/linear_volumes.h"

namespace penumbra::illuminance {

// The points X hidden from an apex by one convex occluder: those for which the open
// segment apex -> X meets the occluder's interior.
struct HiddenRegion {
  // true when the apex is strictly inside the occluder: every X is hidden.
  bool everywhere = false;
  // otherwise: X is hidden iff every plane is negative at X; no planes: nothing is hidden.
  OpenVolume volume;

  // returns true when x is hidden from the apex.
  bool contains(const Point3& x) const;
  // returns true when no point is hidden.
  bool empty() const { return !everywhere && volume.planes.empty(); }
};

// computes the region hidden from `apex` by `occluder`:
// - apex outside the closed occluder: the open shadow volume of the occluder seen from
//   the apex, i.e. the pyramid from the apex through its contour, cut by the faces
//   turned toward it (section 4.1.1, point_shadow_volume of the shadow layer);
// - apex on the boundary of a solid: the open cone of directions strictly into every
//   face through the apex (the planes of those faces);
// - apex strictly inside a solid: everything.
// A flat polygon hides nothing from a point in its plane.
HiddenRegion hidden_region(const ConvexPolyhedron& occluder, const Point3& apex);

// An open interval (low, high) of parameters u along a source a -> b, Q(u) = a + u (b - a),
// with 0 <= low < high <= 1: exact rationals.
struct ExactInterval {
  Exact low;
  Exact high;
};

// computes the parameters u in (0, 1) with Q(u) in `region` (an open interval, since the
// region is an intersection of open half-spaces), or {} when there are none: the blocked
// sub-segment of the source a -> b seen from the region's apex. Exact.
std::optional<ExactInterval> hidden_interval(const HiddenRegion& region, const Point3& a,
                                             const Point3& b);

// What hidden_interval(hidden_region(occluder, apex), a, b) returns, certified by interval
// arithmetic from the doubles given (each taken as the rational it is), or unknown.
struct HiddenIntervalBounds {
  enum class Verdict {
    nothing,   // certainly no parameter is hidden
    interval,  // the exact ends lie in [low] and [high]
    unknown    // intervals cannot decide: ask the exact functions
  };
  Verdict verdict = Verdict::unknown;
  Interval low{0}, high{0};
};

// computes, in interval arithmetic, the sub-segment of the source a -> b hidden from apex
// by a solid (not flat) occluder: the filter of hidden_region and hidden_interval, as in
// CGAL's filtered predicates. A verdict other than unknown is certain; a flat occluder,
// an apex not certainly outside the occluder, or any uncertain sign gives unknown.
HiddenIntervalBounds hidden_interval_filter(const ConvexPolyhedron& occluder, const Vec3d& apex,
                                            const Vec3d& a, const Vec3d& b);

// computes the parameters u in (0, 1) strictly on the positive side of the plane through
// `point` with normal `normal` (any length > 0): the part of the source a -> b on the outer
// side of the receiving face (Fig. 7, S3), exactly. {} when there is none.
std::optional<ExactInterval> outer_side_interval_exact(const Point3& point, const Vector3& normal,
                                                       const Point3& a, const Point3& b);

// computes the parts of `within` not covered by the union of the open intervals `hidden`
// (any order, may overlap): the visible sub-segments of the source, as closed intervals in
// increasing order. Intervals of zero length are dropped (they carry no light).
std::vector<ExactInterval> visible_intervals(const ExactInterval& within,
                                             std::vector<ExactInterval> hidden);

// returns true when the open ray from `point` along `toward` (any length > 0) meets the
// occluder's interior (a flat polygon's relative interior): the point is in the shadow
// of a directional source shining along -toward. Exact.
bool ray_hidden(const ConvexPolyhedron& occluder, const Point3& point, const Vector3& toward);

}  // namespace penumbra::illuminance
