#pragma once
// Interval filters of the illuminance solver (private), as in CGAL's filtered predicates:
// interval arithmetic (geometry/interval.h) on the approximations of the exact objects
// and on the query's doubles certifies most signs; a sign it cannot certify is left to
// the exact test. No epsilon decides anything: an uncertain interval only costs the time
// of the exact test.

#include <vector>

#include "box_cull.h"
#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/interval.h"
#include "penumbra/scene/scene.h"

namespace penumbra::illuminance::detail {

// A filter's verdict: certainly not, certainly, or "ask the exact test".
enum class Certainly { no, yes, unknown };

// returns n.(to - from) with n and both points given as doubles. Needs upward rounding.
Interval dot_difference(const Vec3d& n, const Vec3d& to, const Vec3d& from);

// whether x is strictly inside an open convex volume (its planes).
Certainly inside_open_volume(const std::vector<Plane3>& planes, const Vec3d& x);

// whether x is strictly inside a solid (on the negative side of every face).
Certainly inside_solid(const ConvexPolyhedron& solid, const Vec3d& x);

// whether n.(target - point) > 0: target strictly on the outer side of the receiving plane.
Certainly outer_side(const Vec3d& normal, const Vec3d& target, const Vec3d& point);

// whether the open ray point + t toward, t > 0 (with `end`: the open segment from point to
// end, 0 < t < 1, toward = end - point), meets the interior of a solid (not flat):
// ray_hidden's one-dimensional clip by the face planes, in intervals.
Certainly ray_meets_solid(const ConvexPolyhedron& solid, const Vec3d& point, const Vec3d& toward,
                          const Vec3d* end = nullptr);

// whether the open ray point + t toward, t > 0, meets the relative interior of a flat
// polygon: it crosses the plane once, at t > 0, strictly inside every edge (ray_hidden).
Certainly ray_meets_polygon(const ConvexPolyhedron& polygon, const Vec3d& point,
                            const Vec3d& toward);

// An object as the solver tests it: its exact solid and its box.
struct Occluder {
  const ConvexPolyhedron* solid;
  Box box;
};

// returns true when intervals certify that no open segment from point to a point of the
// source a b meets the occluder's interior (a flat polygon's relative interior), by a
// separating axis of the closed triangle (point, a, b) and the occluder: one of the
// occluder's face normals (the triangle on the closed outer side of the face; strictly for
// a flat polygon, whose relative interior lies on its plane), or, against the occluder's
// box, the triangle's normal and the cross products of its edges with x, y and z
// (Akenine-Moller's triangle-box test). Touching projections separate: the interior
// projects to an open interval.
bool misses_triangle(const Occluder& occluder, const Vec3d& point, const Vec3d& a, const Vec3d& b);

// What the cheap tests say of one occluder and a tube seen from point, before any exact
// work: it certainly hides nothing (its box misses the triangle's, or a separating axis),
// certainly hides the whole tube (a solid meeting both rays to the tube's ends, when the
// whole tube is on the outer side: the hidden points of one convex occluder form an
// interval), or must be examined.
enum class TubeCull { misses, hides_all, examine };

TubeCull cull_for_tube(const Occluder& occluder, const Box& triangle, const Vec3d& point,
                       const LinearLight& light, bool whole_source);

}  // namespace penumbra::illuminance::detail
