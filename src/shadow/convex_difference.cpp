#include "convex_difference.h"

#include <algorithm>
#include <vector>

#include "exact_compare.h"
#include "penumbra/geometry/exact.h"

namespace penumbra::detail {
namespace {

// A chord: the run of a polygon's boundary from contact `start` through the window's
// interior to contact `end` (indices into the polygon); the lit side is to its right.
struct Chord {
  std::size_t polygon, start, end;
};

// A point of the window's boundary: on the half-open edge [w_edge, w_edge+1).
struct BoundaryPoint {
  std::size_t edge;
  const Point2* point;
};

}  // namespace

bool strictly_apart(const Ring2& a, const Ring2& b) {
  // Separating axes of convex polygons: some edge of one has the other strictly outside.
  auto separates = [](const Ring2& p, const Ring2& q) {
    for (std::size_t k = 0; k < p.size(); ++k)
      if (std::all_of(q.begin(), q.end(), [&](const Point2& x) {
            return orientation_sign(p[k], p[(k + 1) % p.size()], x) == CGAL::NEGATIVE;
          }))
        return true;
    return false;
  };
  return separates(a, b) || separates(b, a);
}

std::optional<Region2> convex_difference(const Ring2& window, const std::vector<Ring2>& polygons) {
  const std::size_t n = window.size();
  std::vector<Chord> chords;
  std::vector<BoundaryPoint> starts, ends;  // of each chord
  std::vector<Ring2> holes;
  for (std::size_t j = 0; j < polygons.size(); ++j) {
    const Ring2& polygon = polygons[j];
    const std::size_t m = polygon.size();
    // The window's edges through each vertex of the polygon (two at a corner): the
    // polygon lies in the window, so a vertex on an edge's line is on the edge.
    std::vector<std::vector<std::size_t>> edges(m);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < n; ++k)
        if (orientation_sign(window[k], window[(k + 1) % n], polygon[i]) == CGAL::ZERO)
          edges[i].push_back(k);
    // Edge i -> i + 1 of the polygon lies on the boundary when its ends share an edge.
    std::vector<bool> on_boundary(m);
    bool any_contact = false;
    for (std::size_t i = 0; i < m; ++i) {
      const auto& a = edges[i];
      const auto& b = edges[(i + 1) % m];
      on_boundary[i] = std::any_of(a.begin(), a.end(), [&](std::size_t k) {
        return std::find(b.begin(), b.end(), k) != b.end();
      });
      any_contact = any_contact || !a.empty();
    }
    if (!any_contact) {
      holes.emplace_back(polygon.rbegin(), polygon.rend());  // a hole, clockwise
      continue;
    }
    for (std::size_t i = 0; i < m; ++i)
      if (!edges[i].empty() && !on_boundary[i] && !on_boundary[(i + m - 1) % m])
        return std::nullopt;  // a lone contact: lit parts would touch at a point
    auto boundary_point = [&](std::size_t i) {
      for (std::size_t k : edges[i])
        if (!same_point(polygon[i], window[(k + 1) % n])) return BoundaryPoint{k, &polygon[i]};
      return BoundaryPoint{edges[i].front(), &polygon[i]};  // not reached
    };
    for (std::size_t start = 0; start < m; ++start) {
      if (on_boundary[start] || edges[start].empty()) continue;
      std::size_t end = (start + 1) % m;
      while (edges[end].empty()) end = (end + 1) % m;
      chords.push_back({j, start, end});
      starts.push_back(boundary_point(start));
      ends.push_back(boundary_point(end));
    }
  }
  if (!holes.empty()) {
    // Holes are placed by Polygon_set_2 unless the polygon is the only one.
    if (polygons.size() > 1) return std::nullopt;
    return canonical_region({Polygon2{canonical_ring(window), {canonical_ring(holes.front())}}});
  }

  // b comes after a on a's edge (both on it).
  auto ahead = [&](const BoundaryPoint& a, const BoundaryPoint& b) {
    const auto& p = exact_value(*a.point);
    const auto& q = exact_value(*b.point);
    const auto& u = exact_value(window[a.edge]);
    const auto& v = exact_value(window[(a.edge + 1) % n]);
    return CGAL::sign((q.x() - p.x()) * (v.x() - u.x()) + (q.y() - p.y()) * (v.y() - u.y())) ==
           CGAL::POSITIVE;
  };
  // The window vertices passed walking counter-clockwise from a to b (a != b).
  auto turns = [&](const BoundaryPoint& a, const BoundaryPoint& b) {
    const std::size_t steps = (b.edge + n - a.edge) % n;
    return steps == 0 && !ahead(a, b) ? n : steps;
  };
  // The first chord end met walking counter-clockwise from a.
  auto next_end = [&](const BoundaryPoint& a) {
    std::size_t best = 0, best_turns = turns(a, ends[0]);
    for (std::size_t c = 1; c < ends.size(); ++c) {
      const std::size_t t = turns(a, ends[c]);
      if (t < best_turns || (t == best_turns && ahead(ends[c], ends[best]))) {
        best = c;
        best_turns = t;
      }
    }
    return best;
  };

  // Each lit part: from a chord's start, the boundary counter-clockwise to the next
  // chord end, back along that chord to its start, and so on until the first chord
  // closes it (Nishita 1985 section 3.2: the face minus the union of its shadows).
  std::vector<bool> used(chords.size(), false);
  std::vector<Polygon2> parts;
  for (std::size_t first = 0; first < chords.size(); ++first) {
    if (used[first]) continue;
    Ring2 ring;
    std::size_t c = first;
    for (std::size_t guard = 0; guard <= chords.size(); ++guard) {
      const BoundaryPoint& a = starts[c];
      ring.push_back(*a.point);
      const std::size_t d = next_end(a);
      if (used[d]) return std::nullopt;  // not reached for polygons strictly apart
      used[d] = true;
      const std::size_t t = turns(a, ends[d]);
      for (std::size_t s = 1; s <= t; ++s) ring.push_back(window[(a.edge + s) % n]);
      const Ring2& polygon = polygons[chords[d].polygon];
      const std::size_t m = polygon.size();
      for (std::size_t i = chords[d].end;; i = (i + m - 1) % m) {
        if (i == chords[d].start) break;
        ring.push_back(polygon[i]);
      }
      if (d == first) break;
      c = d;
    }
    if (!used[first]) return std::nullopt;
    Ring2 canonical = canonical_ring(ring);
    if (canonical.empty()) return std::nullopt;
    parts.push_back(Polygon2{std::move(canonical), {}});
  }
  return canonical_region(std::move(parts));
}

}  // namespace penumbra::detail
