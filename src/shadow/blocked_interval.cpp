#include "blocked_interval.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <optional>

#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/interval.h"
#include "rational_enclosure.h"

namespace penumbra::detail {
namespace {

// clips the convex polygon to the closed half-space plane <= 0 (Sutherland-Hodgman).
std::vector<RationalPoint3> clip(const std::vector<RationalPoint3>& polygon,
                                 const RationalPlane3& plane) {
  std::vector<RationalPoint3> kept;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const RationalPoint3& a = polygon[k];
    const RationalPoint3& b = polygon[(k + 1) % n];
    const Rational fa = plane_value(plane, a), fb = plane_value(plane, b);
    if (!CGAL::is_positive(fa)) kept.push_back(a);
    if ((CGAL::is_negative(fa) && CGAL::is_positive(fb)) ||
        (CGAL::is_positive(fa) && CGAL::is_negative(fb)))
      kept.push_back(a + (fa / (fa - fb)) * (b - a));
  }
  return kept;
}

// the source parameter where the line from p through x meets the source's line q1 + t d.
Rational parameter_through(const RationalPoint3& p, const RationalPoint3& x,
                           const RationalPoint3& q1, const RationalVector3& d) {
  const RationalVector3 w = x - p;
  const RationalVector3 m = CGAL::cross_product(w, d);
  return -(CGAL::cross_product(w, q1 - p) * m) / (m * m);
}

using detail::enclosure;  // of a rational (rational_enclosure.h), beside that of a point

IntervalPoint enclosure(const RationalPoint3& p) {
  return {enclosure(p.x()), enclosure(p.y()), enclosure(p.z())};
}

// The sign of a plane at a point when its enclosure certifies it (upward rounding).
std::optional<CGAL::Sign> certified_sign(const std::array<Interval, 4>& plane,
                                         const IntervalPoint& x) {
  const Interval f = plane[0] * x[0] + plane[1] * x[1] + plane[2] * x[2] + plane[3];
  if (f.inf() > 0) return CGAL::POSITIVE;
  if (f.sup() < 0) return CGAL::NEGATIVE;
  return std::nullopt;
}

// the sign of plane at x: filtered, then exact.
CGAL::Sign plane_sign(const RationalPlane3& plane, const std::array<Interval, 4>& approx,
                      const RationalPoint3& x, const IntervalPoint& at) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    if (const auto sign = certified_sign(approx, at)) return *sign;
  }
  return CGAL::sign(plane_value(plane, x));
}

// the edge of solid whose closed segment holds x, or -1 (the box of each edge first).
int edge_holding(const RationalSolid& solid, const RationalPoint3& x) {
  const IntervalPoint at = enclosure(x);
  for (std::size_t k = 0; k < solid.edges.size(); ++k) {
    const IntervalPoint& a = solid.approx_vertices[solid.edges[k][0]];
    const IntervalPoint& b = solid.approx_vertices[solid.edges[k][1]];
    bool apart = false;
    for (int i = 0; i < 3 && !apart; ++i)
      apart = at[i].sup() < std::min(a[i].inf(), b[i].inf()) ||
              at[i].inf() > std::max(a[i].sup(), b[i].sup());
    if (apart) continue;
    const RationalPoint3& ea = solid.vertices[solid.edges[k][0]];
    const RationalPoint3& eb = solid.vertices[solid.edges[k][1]];
    if (CGAL::collinear(ea, eb, x) && !CGAL::is_positive((x - ea) * (x - eb)))
      return static_cast<int>(k);
  }
  return -1;
}

}  // namespace

RationalSolid rational_solid(const ConvexPolyhedron& solid) {
  RationalSolid result;
  for (const Point3& p : solid.vertices()) result.vertices.push_back(exact_value(p));
  std::map<std::array<int, 2>, bool> edges;
  for (const Face& face : solid.faces()) {
    result.planes.push_back(exact_value(face.plane));
    const std::size_t n = face.vertex_ids.size();
    for (std::size_t k = 0; k < n; ++k) {
      int a = face.vertex_ids[k], b = face.vertex_ids[(k + 1) % n];
      if (a > b) std::swap(a, b);
      edges[{a, b}] = true;
    }
  }
  if (solid.is_flat()) {
    // The two faces share a plane: bound the polygon by a plane through each edge, along
    // the normal, facing out (edge x n for a counter-clockwise ring seen along n).
    const Face& face = solid.faces().front();
    const RationalVector3 normal = exact_value(face.normal());
    const std::size_t n = face.vertex_ids.size();
    for (std::size_t k = 0; k < n; ++k) {
      const RationalPoint3& a = result.vertices[face.vertex_ids[k]];
      const RationalPoint3& b = result.vertices[face.vertex_ids[(k + 1) % n]];
      result.planes.emplace_back(a, CGAL::cross_product(b - a, normal));
    }
  }
  for (const auto& edge : edges) result.edges.push_back(edge.first);
  for (const RationalPoint3& v : result.vertices) result.approx_vertices.push_back(enclosure(v));
  for (const RationalPlane3& plane : result.planes)
    result.approx_planes.push_back(enclosure(plane));
  return result;
}

BlockedInterval blocked_interval(const RationalSolid& solid, const RationalPoint3& p,
                                 const RationalPoint3& q1, const RationalPoint3& q2) {
  BlockedInterval result;
  const RationalVector3 d = q2 - q1;
  // P in the closed solid: the directions into it (every plane through P negative) hide.
  const IntervalPoint at = enclosure(p);
  bool inside = true, on_boundary = false;
  for (std::size_t k = 0; k < solid.planes.size(); ++k) {
    const CGAL::Sign f = plane_sign(solid.planes[k], solid.approx_planes[k], p, at);
    if (f == CGAL::POSITIVE) inside = false;
    if (f == CGAL::ZERO) on_boundary = true;
  }
  if (inside && !on_boundary) {
    result.kind = BlockedInterval::Kind::full;
    result.low = 0;
    result.high = 1;
    return result;
  }
  if (inside) {
    // On the boundary: the directions strictly into every face through P hide.
    Rational low = 0, high = 1;
    for (const RationalPlane3& plane : solid.planes) {
      if (!CGAL::is_zero(plane_value(plane, p))) continue;
      // plane(q1 + t d) = f1 + t (f2 - f1) < 0
      const Rational f1 = plane_value(plane, q1), f2 = plane_value(plane, q2);
      if (f1 == f2) {
        if (!CGAL::is_negative(f1)) return result;
        continue;
      }
      const Rational root = f1 / (f1 - f2);
      if (f2 > f1)
        high = std::min(high, root);
      else
        low = std::max(low, root);
    }
    if (low >= high) return result;
    result.kind =
        (low == 0 && high == 1) ? BlockedInterval::Kind::full : BlockedInterval::Kind::interval;
    result.low = low;
    result.high = high;
    return result;
  }
  std::vector<RationalPoint3> polygon{p, q1, q2};
  const IntervalPoint corners[3] = {at, enclosure(q1), enclosure(q2)};
  for (std::size_t k = 0; k < solid.planes.size(); ++k) {
    {
      // a plane with the whole triangle strictly inside cuts nothing
      CGAL::Protect_FPU_rounding<true> upward;
      if (std::all_of(std::begin(corners), std::end(corners), [&](const IntervalPoint& c) {
            return certified_sign(solid.approx_planes[k], c) == CGAL::NEGATIVE;
          }))
        continue;
    }
    polygon = clip(polygon, solid.planes[k]);
    if (polygon.empty()) return result;
  }
  result.kind = BlockedInterval::Kind::interval;
  bool first = true;
  RationalPoint3 low_point, high_point;
  for (const RationalPoint3& x : polygon) {
    const Rational t = parameter_through(p, x, q1, d);
    if (first || t < result.low) result.low = t, low_point = x;
    if (first || t > result.high) result.high = t, high_point = x;
    first = false;
  }
  if (!CGAL::is_zero(result.low)) result.low_edge = edge_holding(solid, low_point);
  if (result.high != 1) result.high_edge = edge_holding(solid, high_point);
  if (result.low == 0 && result.high == 1) result.kind = BlockedInterval::Kind::full;
  return result;
}

bool covers_source(std::vector<BlockedInterval> intervals) {
  std::vector<std::pair<Rational, Rational>> parts;
  for (const BlockedInterval& b : intervals) {
    if (b.kind == BlockedInterval::Kind::full) return true;
    if (b.kind == BlockedInterval::Kind::interval) parts.emplace_back(b.low, b.high);
  }
  std::sort(parts.begin(), parts.end());
  Rational reach = 0;
  for (const auto& part : parts) {
    if (part.first > reach) return false;
    reach = std::max(reach, part.second);
  }
  return reach >= 1;
}

EdgeParameter edge_parameter(const RationalPoint3& e0, const RationalPoint3& e1,
                             const RationalPoint3& q1, const RationalPoint3& q2) {
  // The plane through P and the edge has normal n(P) = (E0 - P) x (E1 - P) = c + w x P with
  // c = E0 x E1, w = E1 - E0; it meets q1 + t d where n . (q1 + t d - P) = 0:
  // t = (P . (c - q1 x w) - c . q1) / (P . (d x w) + c . d).
  const RationalVector3 o0 = e0 - CGAL::ORIGIN, o1 = e1 - CGAL::ORIGIN, o = q1 - CGAL::ORIGIN;
  const RationalVector3 c = CGAL::cross_product(o0, o1), w = e1 - e0, d = q2 - q1;
  return {c - CGAL::cross_product(o, w), CGAL::cross_product(d, w), -(c * o), c * d};
}

std::vector<EdgeParameter> edge_parameters(const RationalSolid& solid, const RationalPoint3& q1,
                                           const RationalPoint3& q2) {
  std::vector<EdgeParameter> result;
  for (const auto& edge : solid.edges)
    result.push_back(edge_parameter(solid.vertices[edge[0]], solid.vertices[edge[1]], q1, q2));
  return result;
}

}  // namespace penumbra::detail
