// The visible part of an area source seen from a receiving point, the solver's panel query
// (docs/area-sources.md, "Illuminance"): decided in intervals when they are certain, exactly
// (shadow/source_view.h) otherwise, as the tube's (linear_visibility.cpp).
//
// In intervals the part is built in the source's plane, in coordinates relative to the point:
// the source polygon clipped by half-spaces through the point. An occluder V lying strictly between
// the source's plane and the point hides from it the source points q whose segment from the point
// meets V: when every vertex of V is strictly on the point's side of the source's plane, those
// are the points of the open cone from the point over V, the intersection of the half-spaces
// bounded by the planes through the point and V's silhouette edges (the edges between a face
// the point sees and one it does not). Inclusion and exclusion over the hidden parts then
// follow visible_source's, each intersection one more clip of the previous term, each vertex
// computed afresh from the two planes through the point that meet there. Every sign is
// certified or the exact path answers, so the parts are the exact path's up to the rounding of
// their vertices (known to within 1e-10 of the source's size, or the exact path gives them).

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>

#include "penumbra/illuminance/area_source.h"
#include "penumbra/shadow/source_view.h"
#include "solver_impl.h"

namespace penumbra::illuminance {

using namespace detail;

namespace {

// The most rings inclusion and exclusion may make here before the exact path decides (which
// has the Boolean difference for many overlapping parts).
constexpr std::size_t kMostTerms = 64;

// returns x - P for an exact point x. Needs upward rounding.
IntervalPoint from(const IntervalPoint& p, const Point3& x) {
  return minus(interval_point(x), p);
}

// A convex ring in the source's plane, relative to the receiving point P (P is the origin):
// its vertices, and for each edge k (from vertex k to k + 1) the normal of the plane through
// P that holds it. A vertex made by a clip is the meeting point of two such planes and the
// source's plane, computed from them afresh (as receiver_clip.h does exactly): no chain of
// constructions widens the intervals clip after clip.
struct IntervalRing {
  boost::container::small_vector<IntervalPoint, 12> vertex, edge;
};

// The source's plane relative to P: n . q = offset, n its outward normal: P (q = 0) has
// n . q > offset, and the whole pyramid conv(P, source) n . q >= offset.
struct SourcePlane {
  IntervalPoint normal;
  Interval offset;
};

// Needs upward rounding.
SourcePlane source_plane(const Face& source, const IntervalPoint& p) {
  const auto& plane = source.plane.approx();
  return {{plane.a(), plane.b(), plane.c()}, -plane_value(plane, p)};
}

// returns the point of the source's plane on the planes through P with normals a and b.
// Needs upward rounding.
IntervalPoint meet(const SourcePlane& plane, const IntervalPoint& a, const IntervalPoint& b) {
  const IntervalPoint d = cross(a, b);
  const Interval scale = plane.offset / dot(plane.normal, d);
  return {d[0] * scale, d[1] * scale, d[2] * scale};
}

enum class ClipResult { unchanged, clipped, emptied, uncertain };

// clips a convex ring by the open half-space normal . q > 0 through P (Sutherland and
// Hodgman), every vertex's side certified; a ring wholly inside is unchanged. Needs upward
// rounding.
ClipResult clip(IntervalRing& ring, const IntervalPoint& normal, const SourcePlane& plane) {
  const std::size_t n = ring.vertex.size();
  boost::container::small_vector<Interval, 12> value(n);
  bool all_in = true, all_out = true;
  for (std::size_t i = 0; i < n; ++i) {
    value[i] = dot(normal, ring.vertex[i]);
    if (value[i].inf() > 0)
      all_out = false;
    else if (value[i].sup() < 0)
      all_in = false;
    else
      return ClipResult::uncertain;
  }
  if (all_in) return ClipResult::unchanged;
  if (all_out) {
    ring.vertex.clear();
    ring.edge.clear();
    return ClipResult::emptied;
  }
  IntervalRing kept;
  for (std::size_t i = 0; i < n; ++i) {
    const bool in_i = value[i].inf() > 0, in_j = value[(i + 1) % n].inf() > 0;
    if (in_i) {
      kept.vertex.push_back(ring.vertex[i]);
      kept.edge.push_back(ring.edge[i]);
    }
    if (in_i != in_j) {
      // Edge i crosses the plane: leaving, the boundary goes on along the plane; entering,
      // along edge i.
      kept.vertex.push_back(meet(plane, ring.edge[i], normal));
      kept.edge.push_back(in_i ? normal : ring.edge[i]);
    }
  }
  ring = std::move(kept);
  return ClipResult::clipped;
}

// The open cone from P over a solid: the half-spaces normal . q > 0 through P whose
// intersection it is (see the top of this file); nothing when P's side of a face is
// uncertain. Needs upward rounding.
using Cone = boost::container::small_vector<IntervalPoint, 12>;

std::optional<Cone> cone_over(const ConvexPolyhedron& solid, const IntervalPoint& p) {
  const std::vector<Face>& faces = solid.faces();
  boost::container::small_vector<char, 16> seen(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Interval side = plane_value(faces[f].plane.approx(), p);
    if (!(side.inf() > 0 || side.sup() < 0)) return std::nullopt;
    seen[f] = side.inf() > 0;
  }
  // A silhouette edge a -> b of a face P sees (counter-clockwise seen from outside): with c
  // inside that face, det(a - P, b - P, c - P) = -((b - a) x (c - a)) . (P - a) < 0, so the
  // solid lies on the positive side of (b - P) x (a - P).
  Cone cone;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!seen[f]) continue;
    const Face& face = faces[f];
    for (std::size_t k = 0; k < face.vertices.size(); ++k)
      if (!seen[face.neighbours[k]])
        cone.push_back(cross(from(p, face.vertices[(k + 1) % face.vertices.size()]),
                             from(p, face.vertices[k])));
  }
  return cone;
}

// The planes through P and the source's edges, edge k (from vertex k to k + 1) first: the
// source seen from P as a face is seen (cone_over's formula), so the pyramid conv(P, source)
// lies on their closed positive sides. Needs upward rounding.
Cone edge_planes(const Face& source, const IntervalPoint& p) {
  Cone planes;
  const std::size_t n = source.vertices.size();
  for (std::size_t k = 0; k < n; ++k)
    planes.push_back(cross(from(p, source.vertices[(k + 1) % n]), from(p, source.vertices[k])));
  return planes;
}

// returns true when the box (given relative to P by its corners low and high) is certainly
// strictly outside the closed half-space normal . q >= offset: the greatest value of
// normal . q over the box, the sum over the axes of the greater of its two ends' terms, is
// certainly below offset. Needs upward rounding.
bool outside(const IntervalPoint& low, const IntervalPoint& high, const IntervalPoint& normal,
             const Interval& offset = Interval(0)) {
  double greatest = 0;
  for (int i = 0; i < 3; ++i) {
    // A certainly positive (negative) coefficient is greatest at the upper (lower) end.
    const Interval& n = normal[i];
    const auto term = [&](const Interval& end) { return (n * end).sup(); };
    greatest += n.inf() >= 0   ? term(high[i])
                : n.sup() <= 0 ? term(low[i])
                               : std::max(term(low[i]), term(high[i]));
  }
  return greatest < offset.inf();
}

// returns true when one plane of the closed pyramid conv(P, source) certainly has the box
// strictly outside: a side (edge_planes), or last, as it seldom separates anything, the
// source's plane. Needs upward rounding.
bool outside_pyramid(const Cone& sides, const SourcePlane& base, const Box& box,
                     const IntervalPoint& p) {
  const IntervalPoint low{Interval(box.low[0]) - p[0], Interval(box.low[1]) - p[1],
                          Interval(box.low[2]) - p[2]};
  const IntervalPoint high{Interval(box.high[0]) - p[0], Interval(box.high[1]) - p[1],
                           Interval(box.high[2]) - p[2]};
  return std::any_of(sides.begin(), sides.end(),
                     [&](const IntervalPoint& normal) { return outside(low, high, normal); }) ||
         outside(low, high, base.normal, base.offset);
}

// A convex part of the visible part's signed sum, relative to P in doubles: counted once, or
// taken away.
struct SignedRing {
  boost::container::small_vector<Vec3d, 12> ring;
  bool negative;
};

using SignedRings = boost::container::small_vector<SignedRing, 8>;

// An occluder that may hide part of the source, and whether its vertices all lie certainly
// strictly on the lit side of the source's plane (CachedArea::in_front).
struct NearOccluder {
  const ConvexPolyhedron* solid;
  bool in_front;
};

using NearOccluders = boost::container::small_vector<NearOccluder, 16>;

// returns the signed convex parts whose sum is the visible part of source from P
// (visible_source's), none when nothing is visible, or nothing at all when intervals cannot
// certify a decision (then the exact path answers). edges: edge_planes(source, p); plane:
// source_plane(source, p). Needs upward rounding.
std::optional<SignedRings> visible_filtered(const Face& source, const IntervalPoint& p,
                                            const Cone& edges, const SourcePlane& plane,
                                            const Vec3d& normal, const NearOccluders& near) {
  IntervalRing part;
  for (const Point3& q : source.vertices) part.vertex.push_back(from(p, q));
  part.edge.assign(edges.begin(), edges.end());
  // Fig. 7, S3: the receiving surface hides the part of the source not strictly on its outer
  // side.
  if (clip(part, {Interval(normal[0]), Interval(normal[1]), Interval(normal[2])}, plane) ==
      ClipResult::uncertain)
    return std::nullopt;
  if (part.vertex.empty()) return SignedRings{};
  boost::container::small_vector<Cone, 8> cones;
  boost::container::small_vector<IntervalRing, 8> hidden;
  for (std::size_t k = 0; k < near.size(); ++k) {
    auto cone = cone_over(*near[k].solid, p);
    if (!cone) return std::nullopt;
    IntervalRing shadow = part;
    bool whole = true;
    for (const IntervalPoint& side : *cone) {
      const ClipResult result = clip(shadow, side, plane);
      if (result == ClipResult::uncertain) return std::nullopt;
      if (result == ClipResult::emptied) break;
      whole = whole && result == ClipResult::unchanged;
    }
    // The cone holds every point the occluder hides; it is what the occluder hides when the
    // occluder lies on the lit side of the source's plane (a point v of it on the ray from P
    // through q is then between P and q).
    if (shadow.vertex.empty()) continue;
    if (!near[k].in_front) return std::nullopt;
    // One occluder hides all of it (the usual umbra): nothing is visible, exactly 0.
    if (whole) return SignedRings{};
    hidden.push_back(std::move(shadow));
    cones.push_back(std::move(*cone));
  }
  // The rings become doubles to integrate, as the exact path's do, when their vertices are
  // known to within 1e-10 of the part's size.
  double size = 0;
  for (const IntervalPoint& q : part.vertex)
    for (int i = 0; i < 3; ++i)
      size = std::max(size, std::abs(q[i].inf() - part.vertex[0][i].inf()));
  SignedRings rings;
  const auto keep = [&](const IntervalRing& ring, bool negative) {
    rings.push_back({{}, negative});
    for (const IntervalPoint& q : ring.vertex) {
      for (int i = 0; i < 3; ++i)
        if (!(q[i].sup() - q[i].inf() <= 1e-10 * size)) return false;
      rings.back().ring.push_back(
          {CGAL::to_double(q[0]), CGAL::to_double(q[1]), CGAL::to_double(q[2])});
    }
    return true;
  };
  // part - sum H_i + sum H_i ^ H_j - ...: depth first over the subsets in increasing order,
  // each intersection the previous one clipped by one more cone (its vertices computed from
  // their planes, not from the previous vertices); an empty one ends a branch.
  const auto add = [&](const auto& self, const IntervalRing& ring, std::size_t first,
                       std::size_t count) -> bool {
    for (std::size_t i = first; i < cones.size(); ++i) {
      IntervalRing both = count == 0 ? hidden[i] : ring;
      for (std::size_t h = 0; count > 0 && h < cones[i].size() && !both.vertex.empty(); ++h)
        if (clip(both, cones[i][h], plane) == ClipResult::uncertain) return false;
      if (both.vertex.empty()) continue;
      if (rings.size() >= kMostTerms || !keep(both, count % 2 == 0) ||
          !self(self, both, i + 1, count + 1))
        return false;
    }
    return true;
  };
  if (!keep(part, false) || !add(add, part, 0, 0)) return std::nullopt;
  return rings;
}

}  // namespace

CachedArea detail::cache_area(const AreaLight& panel, const std::vector<Occluder>& occluders) {
  CachedArea cached{&panel, {panel.vertices[0], panel.vertices[0]}, {}};
  for (const Vec3d& q : panel.vertices)
    for (int i = 0; i < 3; ++i) {
      cached.box.low[i] = std::min(cached.box.low[i], q[i]);
      cached.box.high[i] = std::max(cached.box.high[i], q[i]);
    }
  const CGAL::Protect_FPU_rounding<true> upward;
  for (std::size_t f = 0; f < 2; ++f) {
    const auto& plane = panel.polygon->faces()[f].plane.approx();
    for (const Occluder& occluder : occluders) {
      const auto& vertices = occluder.solid->vertices();
      cached.in_front[f].push_back(std::all_of(
          vertices.begin(), vertices.end(),
          [&](const Point3& v) { return plane_value(plane, interval_point(v)).inf() > 0; }));
    }
  }
  return cached;
}

double IlluminanceSolver::Impl::area_light(const CachedArea& panel, const QueryPoint& point,
                                           const Vec3d& normal, OccluderSubset subset) const {
  const AreaLight& light = *panel.light;
  const Face* source = &light.polygon->faces()[light.front];
  NearOccluders near;
  std::optional<SignedRings> parts;
  {
    const CGAL::Protect_FPU_rounding<true> upward;
    // The side of the source turned toward the point (a one-sided source has one).
    const Interval value = plane_value(source->plane.approx(), point.doubles());
    const CGAL::Oriented_side side = value.inf() > 0   ? CGAL::ON_POSITIVE_SIDE
                                     : value.sup() < 0 ? CGAL::ON_NEGATIVE_SIDE
                                                       : source->plane.oriented_side(point.exact());
    if (side != CGAL::ON_POSITIVE_SIDE) {
      if (!light.two_sided || side == CGAL::ON_ORIENTED_BOUNDARY) return 0;
      source = &light.polygon->faces()[1 - light.front];
    }
    const std::vector<char>& in_front =
        panel.in_front[source == &light.polygon->faces()[0] ? 0 : 1];
    // The occluders whose box meets the box of the point and the source (a superset of those
    // that meet conv(point, source)), less those whose box one of the pyramid's planes
    // certainly separates from it; both paths clip the others, visible_source after its own
    // test of the solid.
    Box reach = panel.box;
    for (int i = 0; i < 3; ++i) {
      reach.low[i] = std::min(reach.low[i], point.doubles()[i]);
      reach.high[i] = std::max(reach.high[i], point.doubles()[i]);
    }
    const IntervalPoint p{Interval(point.doubles()[0]), Interval(point.doubles()[1]),
                          Interval(point.doubles()[2])};
    const Cone edges = edge_planes(*source, p);
    const SourcePlane plane = source_plane(*source, p);
    any_occluder(occluders.size(), subset, [&](std::size_t k) {
      if (overlap(occluders[k].box, reach) && !outside_pyramid(edges, plane, occluders[k].box, p))
        near.push_back({occluders[k].solid, in_front[k] != 0});
      return false;
    });
    parts = visible_filtered(*source, p, edges, plane, normal, near);
  }
  // Lambert's closed form over the visible part's boundary: rings counter-clockwise in the
  // source's frame are counter-clockwise seen from the point (area_source.h), and the edge sum
  // of a clockwise ring is negative: the signed sum over visible_source's rings is the visible
  // part's.
  // The signed sum of parts that cancel (a source hidden by several occluders together) may
  // round below 0; the visible part's measure is not negative.
  if (parts) {
    double omega = 0;
    for (const SignedRing& part : *parts)
      omega += (part.negative ? -1 : 1) *
               projected_solid_angle({0, 0, 0}, normal, part.ring.data(), part.ring.size());
    return light.luminance * std::max(0.0, omega);
  }
  std::vector<const ConvexPolyhedron*> occluder_solids;
  for (const NearOccluder& occluder : near) occluder_solids.push_back(occluder.solid);
  std::vector<std::vector<Vec3d>> rings;
  for (const Ring2& ring :
       visible_source(*source, point.exact(), Plane3(point.exact(), to_exact_vector(normal)),
                      occluder_solids)) {
    rings.emplace_back();
    for (const Point2& q : ring) rings.back().push_back(to_double(source->frame.to_world(q)));
  }
  return light.luminance * std::max(0.0, projected_solid_angle(point.doubles(), normal, rings));
}

}  // namespace penumbra::illuminance
