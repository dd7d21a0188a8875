#include "edge_rings.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace penumbra::detail {
namespace {

std::uint64_t directed(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

// Union-find over triangles joined across shared edges.
struct Components {
  std::vector<int> parent;
  explicit Components(std::size_t count) : parent(count) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

// One boundary edge: ring, position in the ring, and its box in doubles.
struct Edge {
  std::size_t ring, position;
  CGAL::Bbox_2 box;
};

// true when the boundary edges of rings touch only where consecutive edges of one ring
// share their vertex (and do not fold back onto each other there): the rings are simple
// and disjoint. A sweep over the edges' boxes along x; exact tests for boxes that meet.
bool simple_and_disjoint(const std::vector<std::vector<Point2>>& rings) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t k = 0; k < rings[r].size(); ++k)
      edges.push_back({r, k, rings[r][k].bbox() + rings[r][(k + 1) % rings[r].size()].bbox()});
  std::sort(edges.begin(), edges.end(),
            [](const Edge& a, const Edge& b) { return a.box.xmin() < b.box.xmin(); });
  const auto segment = [&](const Edge& e) {
    const auto& ring = rings[e.ring];
    return Segment2(ring[e.position], ring[(e.position + 1) % ring.size()]);
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size() && edges[j].box.xmin() <= edges[i].box.xmax();
         ++j) {
      if (!CGAL::do_overlap(edges[i].box, edges[j].box)) continue;
      const Edge *a = &edges[i], *b = &edges[j];
      if (a->ring == b->ring) {
        const std::size_t n = rings[a->ring].size();
        if ((b->position + 1) % n == a->position) std::swap(a, b);
        if ((a->position + 1) % n == b->position) {
          // a = (p, q), b = (q, r): they meet at q; they overlap when r lies on the ray
          // from q through p.
          const auto& ring = rings[a->ring];
          const Point2& p = ring[a->position];
          const Point2& q = ring[b->position];
          const Point2& r = ring[(b->position + 1) % n];
          if (CGAL::collinear(p, q, r) && !CGAL::collinear_are_strictly_ordered_along_line(p, q, r))
            return false;
          continue;
        }
      }
      if (CGAL::do_intersect(segment(*a), segment(*b))) return false;
    }
  }
  return true;
}

// +1 for a counter-clockwise simple ring, -1 for a clockwise one: the turn at its
// lexicographically smallest vertex.
int orientation_of(const std::vector<Point2>& ring) {
  const std::size_t n = ring.size();
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (CGAL::compare_xy(ring[i], ring[k]) == CGAL::SMALLER) k = i;
  return CGAL::orientation(ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]) == CGAL::LEFT_TURN
             ? 1
             : -1;
}

// the winding number around q of the rings other than skip, with a box test first.
int winding_of_others(const std::vector<std::vector<Point2>>& rings,
                      const std::vector<CGAL::Bbox_2>& boxes, std::size_t skip, const Point2& q) {
  int winding = 0;
  const CGAL::Bbox_2 point = q.bbox();
  for (std::size_t s = 0; s < rings.size(); ++s)
    if (s != skip && CGAL::do_overlap(boxes[s], point)) winding += winding_number(rings[s], q);
  return winding;
}

}  // namespace

int winding_number(const std::vector<Point2>& ring, const Point2& q) {
  int winding = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % ring.size()];
    if (a.y() <= q.y()) {
      if (b.y() > q.y() && CGAL::orientation(a, b, q) == CGAL::LEFT_TURN) ++winding;
    } else if (b.y() <= q.y() && CGAL::orientation(a, b, q) == CGAL::RIGHT_TURN) {
      --winding;
    }
  }
  return winding;
}

std::optional<std::vector<EdgeRingFace>> edge_ring_faces(
    const std::vector<std::array<int, 3>>& triangles, const std::vector<Point2>& points) {
  // Each directed edge once; an edge run both ways is inside (its triangles join).
  std::unordered_map<std::uint64_t, int> edge_triangle;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (!edge_triangle
               .emplace(directed(triangles[t][k], triangles[t][(k + 1) % 3]), static_cast<int>(t))
               .second)
        return std::nullopt;
  Components components(triangles.size());
  std::unordered_map<int, std::pair<int, int>> next;  // boundary: vertex -> (vertex, triangle)
  for (const auto& [key, t] : edge_triangle) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    const auto back = edge_triangle.find(directed(b, a));
    if (back != edge_triangle.end())
      components.join(t, back->second);
    else if (!next.emplace(a, std::make_pair(b, t)).second)
      return std::nullopt;  // the boundary meets itself at a
  }

  // Chain the boundary into rings, each started at its smallest vertex index (so the
  // result does not depend on hashing).
  std::vector<int> starts;
  for (const auto& entry : next) starts.push_back(entry.first);
  std::sort(starts.begin(), starts.end());
  std::unordered_set<int> used;
  std::vector<std::vector<int>> rings;
  std::vector<int> ring_component;
  for (int start : starts) {
    if (used.count(start)) continue;
    std::vector<int> ring;
    for (int v = start; !used.count(v);) {
      used.insert(v);
      ring.push_back(v);
      const auto step = next.find(v);
      if (step == next.end()) return std::nullopt;
      v = step->second.first;
      if (used.count(v) && v != start) return std::nullopt;
    }
    ring_component.push_back(components.find(next.at(start).second));
    rings.push_back(std::move(ring));
  }

  std::vector<std::vector<Point2>> shapes(rings.size());
  std::vector<CGAL::Bbox_2> boxes(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (rings[r].size() < 3) return std::nullopt;
    for (int v : rings[r]) {
      shapes[r].push_back(points[v]);
      boxes[r] += points[v].bbox();
    }
  }
  if (!simple_and_disjoint(shapes)) return std::nullopt;

  // Covered once: just inside a counter-clockwise ring the winding number is 1 and just
  // outside 0; just inside a clockwise one 0 and outside 1.
  std::vector<int> orientation(rings.size());
  std::vector<int> around(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    orientation[r] = orientation_of(shapes[r]);
    around[r] = winding_of_others(shapes, boxes, r, shapes[r][0]);
    if (around[r] != (orientation[r] > 0 ? 0 : 1)) return std::nullopt;
  }

  // Each hole belongs to the innermost outer ring around it: the one that itself lies
  // inside the most outer rings; both must be one component of triangles.
  std::vector<EdgeRingFace> faces;
  std::vector<int> face_of(rings.size(), -1);
  std::unordered_set<int> components_with_a_face;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (orientation[r] < 0) continue;
    if (!components_with_a_face.insert(ring_component[r]).second) return std::nullopt;
    face_of[r] = static_cast<int>(faces.size());
    faces.push_back({rings[r], {}, 0});
  }
  std::vector<int> depth(rings.size(), -1);  // outer rings around an outer ring, when asked
  const auto inside = [&](std::size_t s, std::size_t r) {
    return CGAL::do_overlap(boxes[s], shapes[r][0].bbox()) &&
           winding_number(shapes[s], shapes[r][0]) != 0;
  };
  for (std::size_t h = 0; h < rings.size(); ++h) {
    if (orientation[h] > 0) continue;
    int parent = -1;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      if (orientation[r] < 0 || !inside(r, h)) continue;
      if (depth[r] < 0) {
        depth[r] = 0;
        for (std::size_t s = 0; s < rings.size(); ++s)
          if (s != r && orientation[s] > 0 && inside(s, r)) ++depth[r];
      }
      if (parent < 0 || depth[r] > depth[parent]) parent = static_cast<int>(r);
    }
    if (parent < 0 || ring_component[parent] != ring_component[h]) return std::nullopt;
    faces[face_of[parent]].holes.push_back(rings[h]);
  }
  std::unordered_map<int, std::size_t> size;
  for (std::size_t t = 0; t < triangles.size(); ++t) ++size[components.find(static_cast<int>(t))];
  std::size_t counted = 0;
  for (std::size_t r = 0; r < rings.size(); ++r)
    if (face_of[r] >= 0) counted += faces[face_of[r]].triangles = size[ring_component[r]];
  if (counted != triangles.size()) return std::nullopt;  // a component without an outer ring
  return faces;
}

}  // namespace penumbra::detail
