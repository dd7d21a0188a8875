#include "blocked_interval_filter.h"

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <set>

#include "rational_enclosure.h"

namespace penumbra::detail {
namespace {

enum Side : unsigned { kPQ1 = 1, kPQ2 = 2, kQ1Q2 = 4 };

// Short lists kept inline (a vertex lies on few planes, the clipped triangle has few
// vertices): this filter runs for most points the sweep labels, and heap lists were a third
// of its time.
template <class T>
using Short = boost::container::small_vector<T, 8>;
using PlaneIds = boost::container::small_vector<int, 4>;

struct Vertex {
  IntervalPoint x;
  unsigned sides;  // the triangle's sides it lies on
  PlaneIds on;     // the solid's geometric planes it lies on, increasing
};

Interval value(const std::array<Interval, 4>& plane, const IntervalPoint& x) {
  return plane[0] * x[0] + plane[1] * x[1] + plane[2] * x[2] + plane[3];
}

// -1, 0, +1 when certain, nullopt otherwise (0 only for an exact zero).
std::optional<int> sign_of(const Interval& v) {
  if (v.inf() > 0) return 1;
  if (v.sup() < 0) return -1;
  if (v.inf() == 0 && v.sup() == 0) return 0;
  return std::nullopt;
}

PlaneIds common(const PlaneIds& a, const PlaneIds& b) {
  PlaneIds result;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(result));
  return result;
}

void add(PlaneIds& on, int plane) {
  const auto at = std::lower_bound(on.begin(), on.end(), plane);
  if (at == on.end() || *at != plane) on.insert(at, plane);
}

// the source parameter where the line from p through x meets the line q1 + t d.
std::optional<Interval> parameter_through(const IntervalPoint& p, const IntervalPoint& x,
                                          const IntervalPoint& q1, const IntervalPoint& d) {
  const IntervalPoint w = minus(x, p);
  const IntervalPoint m = cross(w, d);
  const Interval mm = dot(m, m);
  if (!(mm.inf() > 0)) return std::nullopt;
  return -dot(cross(w, minus(q1, p)), m) / mm;
}

// certain a < b, certain a >= b, or nullopt.
std::optional<bool> less(const Interval& a, const Interval& b) {
  if (a.sup() < b.inf()) return true;
  if (a.inf() >= b.sup()) return false;
  return std::nullopt;
}

// the intersection of two enclosures of one value.
Interval both(const Interval& a, const Interval& b) {
  return Interval(std::max(a.inf(), b.inf()), std::min(a.sup(), b.sup()));
}

}  // namespace

IntervalPoint interval_point(const RationalPoint3& p) {
  return {enclosure(p.x()), enclosure(p.y()), enclosure(p.z())};
}

IntervalSolid interval_solid(const RationalSolid& solid) {
  IntervalSolid result;
  const std::size_t n = solid.planes.size();
  result.planes = solid.approx_planes;
  // Geometric ids: a plane equal to an earlier one (either orientation) shares its id.
  for (std::size_t k = 0; k < n; ++k) {
    int id = static_cast<int>(k);
    for (std::size_t j = 0; j < k && id == static_cast<int>(k); ++j) {
      const RationalPlane3& a = solid.planes[j];
      const RationalPlane3& b = solid.planes[k];
      if (a == b || a == b.opposite()) id = result.geometric[j];
    }
    result.geometric.push_back(id);
  }
  // whether vertex v lies on plane k: off it when the intervals certify a nonzero value,
  // else exactly.
  const auto on_plane = [&](std::size_t v, std::size_t k) {
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const Interval f = value(solid.approx_planes[k], solid.approx_vertices[v]);
      if (f.inf() > 0 || f.sup() < 0) return false;
    }
    const RationalPlane3& plane = solid.planes[k];
    const RationalPoint3& x = solid.vertices[v];
    return CGAL::is_zero(plane.a() * x.x() + plane.b() * x.y() + plane.c() * x.z() + plane.d());
  };
  for (std::size_t e = 0; e < solid.edges.size(); ++e) {
    PlaneIds ids;
    for (std::size_t k = 0; k < n; ++k)
      if (on_plane(solid.edges[e][0], k) && on_plane(solid.edges[e][1], k))
        add(ids, result.geometric[k]);
    if (ids.size() == 2) result.edge_of[{ids[0], ids[1]}] = static_cast<int>(e);
  }
  return result;
}

void enclose_edge_parameters(IntervalSolid& solid, const std::vector<EdgeParameter>& edges) {
  solid.edge_parameters.clear();
  for (const EdgeParameter& t : edges) {
    solid.edge_parameters.push_back({enclosure(t.gn.x()), enclosure(t.gn.y()), enclosure(t.gn.z()),
                                     enclosure(t.hn), enclosure(t.gd.x()), enclosure(t.gd.y()),
                                     enclosure(t.gd.z()), enclosure(t.hd)});
  }
}

std::optional<BlockedBounds> blocked_bounds(const IntervalSolid& solid, const IntervalPoint& p,
                                            const IntervalPoint& q1, const IntervalPoint& q2) {
  // P certainly outside (some plane certainly positive); otherwise the exact path decides.
  bool outside = false;
  for (const auto& plane : solid.planes) {
    const auto sign = sign_of(value(plane, p));
    if (sign && *sign > 0) outside = true;
  }
  if (!outside) return std::nullopt;
  Short<Vertex> polygon{{p, kPQ1 | kPQ2, {}}, {q1, kPQ1 | kQ1Q2, {}}, {q2, kPQ2 | kQ1Q2, {}}};
  for (std::size_t k = 0; k < solid.planes.size() && !polygon.empty(); ++k) {
    const int id = solid.geometric[k];
    Short<int> signs;
    for (const Vertex& v : polygon) {
      // on a plane already met (a flat polygon's other face): exactly on it
      if (std::binary_search(v.on.begin(), v.on.end(), id)) {
        signs.push_back(0);
        continue;
      }
      const auto sign = sign_of(value(solid.planes[k], v.x));
      if (!sign) return std::nullopt;
      signs.push_back(*sign);
    }
    Short<Vertex> kept;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vertex& a = polygon[i];
      const Vertex& b = polygon[(i + 1) % n];
      const int sa = signs[i], sb = signs[(i + 1) % n];
      if (sa <= 0) {
        kept.push_back(a);
        if (sa == 0) add(kept.back().on, id);
      }
      if (sa * sb < 0) {
        const Interval fa = value(solid.planes[k], a.x), fb = value(solid.planes[k], b.x);
        const Interval r = fa / (fa - fb);
        Vertex crossing{{a.x[0] + r * (b.x[0] - a.x[0]), a.x[1] + r * (b.x[1] - a.x[1]),
                         a.x[2] + r * (b.x[2] - a.x[2])},
                        a.sides & b.sides,
                        common(a.on, b.on)};
        add(crossing.on, id);
        kept.push_back(std::move(crossing));
      }
    }
    polygon = std::move(kept);
  }
  BlockedBounds result;
  if (polygon.empty()) return result;
  const IntervalPoint d = minus(q2, q1);
  struct End {
    Interval t;
    bool clamp;
    const Vertex* vertex;
    int edge = -1;  // the edge whose parameter at p enclosed t (by_edge), or -1
  };
  Short<End> ends;
  // The end of a vertex on an edge, from the edge's parameter at p. Its denominator is zero
  // where p, the edge and the source are coplanar; certified nonzero, the edge's line meets
  // the triangle's plane in one point, so every clipped vertex on the edge is that point.
  const auto by_edge = [&](const Vertex& v) -> std::optional<std::pair<Interval, int>> {
    if (solid.edge_parameters.empty() || v.on.size() != 2) return std::nullopt;
    const auto found = solid.edge_of.find({v.on[0], v.on[1]});
    if (found == solid.edge_of.end()) return std::nullopt;
    const std::array<Interval, 8>& g = solid.edge_parameters[found->second];
    const Interval den = g[4] * p[0] + g[5] * p[1] + g[6] * p[2] + g[7];
    if (!(den.inf() > 0 || den.sup() < 0)) return std::nullopt;
    return std::pair{(g[0] * p[0] + g[1] * p[1] + g[2] * p[2] + g[3]) / den, found->second};
  };
  for (const Vertex& v : polygon) {
    if (v.sides & kPQ1) {
      ends.push_back({Interval(0), true, &v});
    } else if (v.sides & kPQ2) {
      ends.push_back({Interval(1), true, &v});
    } else {
      if (v.sides) return std::nullopt;  // on the source's side: the exact path says why
      auto t = parameter_through(p, v.x, q1, d);
      const auto e = by_edge(v);
      if (e) t = t ? both(*t, e->first) : e->first;
      if (!t) return std::nullopt;
      ends.push_back({*t, false, &v, e ? e->second : -1});
    }
  }
  // The extreme ends must be certain: strictly beyond every other, or the same clamp.
  const auto extreme = [&](bool lowest) -> std::optional<std::size_t> {
    std::size_t best = 0;
    for (std::size_t i = 1; i < ends.size(); ++i)
      if (lowest ? ends[i].t.inf() < ends[best].t.inf() : ends[i].t.sup() > ends[best].t.sup())
        best = i;
    for (std::size_t i = 0; i < ends.size(); ++i) {
      if (i == best) continue;
      if (ends[i].clamp && ends[best].clamp && ends[i].t.inf() == ends[best].t.inf()) continue;
      if (ends[i].edge >= 0 && ends[i].edge == ends[best].edge) continue;  // the same point
      const auto certain = lowest ? less(ends[best].t, ends[i].t) : less(ends[i].t, ends[best].t);
      if (!certain || !*certain) return std::nullopt;
    }
    return best;
  };
  const auto low = extreme(true), high = extreme(false);
  if (!low || !high) return std::nullopt;
  const auto edge_of = [&](const End& end) -> std::optional<int> {
    if (end.clamp) return -1;
    const PlaneIds& on = end.vertex->on;
    if (on.size() != 2) return std::nullopt;
    const auto found = solid.edge_of.find({on[0], on[1]});
    if (found == solid.edge_of.end()) return std::nullopt;
    return found->second;
  };
  const auto low_edge = edge_of(ends[*low]), high_edge = edge_of(ends[*high]);
  if (!low_edge || !high_edge) return std::nullopt;
  result.low = ends[*low].t;
  result.high = ends[*high].t;
  result.low_clamped = ends[*low].clamp;
  result.high_clamped = ends[*high].clamp;
  if (result.low_clamped && result.low.inf() != 0) return std::nullopt;  // only t = 1 seen
  if (result.high_clamped && result.high.sup() != 1) return std::nullopt;
  result.low_edge = *low_edge;
  result.high_edge = *high_edge;
  result.kind = result.low_clamped && result.high_clamped ? BlockedInterval::Kind::full
                                                          : BlockedInterval::Kind::interval;
  return result;
}

std::optional<bool> covers_source(const std::vector<BlockedBounds>& intervals) {
  std::vector<const BlockedBounds*> parts;
  for (const BlockedBounds& b : intervals) {
    if (b.kind == BlockedInterval::Kind::full) return true;
    if (b.kind == BlockedInterval::Kind::interval) parts.push_back(&b);
  }
  // 0 is covered only by an end clamped to it (other ends are strictly inside (0, 1)).
  if (std::none_of(parts.begin(), parts.end(), [](const auto* b) { return b->low_clamped; }))
    return false;
  // Every right end short of 1 must lie in another interval that goes on beyond it.
  for (const BlockedBounds* j : parts) {
    if (j->high_clamped) continue;
    bool continued = false, unknown = false;
    for (const BlockedBounds* k : parts) {
      if (k == j) continue;
      const std::optional<bool> starts_after =
          k->low_clamped ? std::optional<bool>(false) : less(j->high, k->low);
      const std::optional<bool> ends_after =
          k->high_clamped ? std::optional<bool>(true) : less(j->high, k->high);
      if (starts_after && ends_after) {
        if (!*starts_after && *ends_after) continued = true;
      } else if (!(starts_after && *starts_after) && !(ends_after && !*ends_after)) {
        unknown = true;  // some sign undecided, and k not certainly out
      }
      if (continued) break;
    }
    if (continued) continue;
    if (unknown) return std::nullopt;
    return false;
  }
  return true;
}

}  // namespace penumbra::detail
