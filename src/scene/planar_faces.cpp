#include "planar_faces.h"

#include "edge_rings.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/point_order.h"

#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>

namespace penumbra {
namespace {

using Polygon2 = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet2 = CGAL::Polygon_set_2<Kernel>;

// === Equal points

// returns, for each point, the index of the first point exactly equal to it, and adds to
// merged how many points were equal to an earlier one. Points are sorted by their double
// approximations (equal rationals round alike) and exactly within equal approximations.
std::vector<int> first_equal_points(const std::vector<RationalPoint3>& points,
                                    std::size_t& merged) {
  using Approx = std::array<double, 3>;
  std::vector<Approx> approx(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    approx[i] = {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                 CGAL::to_double(points[i].z())};
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (approx[a] != approx[b]) return approx[a] < approx[b];
    const auto c = CGAL::compare_xyz(points[a], points[b]);
    return c != CGAL::EQUAL ? c == CGAL::SMALLER : a < b;
  });
  std::vector<int> first(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int i = order[k];
    if (k > 0 && approx[order[k - 1]] == approx[i] && points[order[k - 1]] == points[i]) {
      first[i] = first[order[k - 1]];
      ++merged;
    } else {
      first[i] = i;
    }
  }
  return first;
}

// === Projection onto a coordinate plane

// The plane of a face projected along the axis where its normal is largest, with the two
// remaining axes ordered so that counter-clockwise in 2D is counter-clockwise seen from the
// normal's side (the projection is a linear map, so every 2D sign is exact).
struct Projection {
  int first = 0, second = 1;

  explicit Projection(const RationalVector3& normal) {
    const double n[3] = {std::abs(CGAL::to_double(normal.x())),
                         std::abs(CGAL::to_double(normal.y())),
                         std::abs(CGAL::to_double(normal.z()))};
    int axis = 2;
    if (n[0] >= n[1] && n[0] >= n[2]) axis = 0;
    if (n[1] > n[0] && n[1] >= n[2]) axis = 1;
    if (CGAL::is_zero(normal[axis])) {  // a tie in doubles hid the larger component
      for (int k = 0; k < 3; ++k)
        if (!CGAL::is_zero(normal[k])) axis = k;
    }
    first = (axis + 1) % 3;
    second = (axis + 2) % 3;
    if (CGAL::is_negative(normal[axis])) std::swap(first, second);
  }

  // twice the signed area of the triangle (a, b, c) seen from the normal's side.
  Rational cross(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c) const {
    return (b[first] - a[first]) * (c[second] - a[second]) -
           (b[second] - a[second]) * (c[first] - a[first]);
  }
};

// === Triangle adjacency

// One use of an edge by a triangle: the edge from corner slot to corner slot + 1.
struct EdgeUse {
  std::uint64_t key;  // smaller vertex index in the high half
  int triangle;
  int slot;
};

std::uint64_t edge_key(int a, int b) {
  const auto low = static_cast<std::uint64_t>(std::min(a, b));
  const auto high = static_cast<std::uint64_t>(std::max(a, b));
  return (low << 32) | high;
}

// Across each corner slot of each triangle: the triangle sharing that edge when exactly two
// use it (a manifold edge), -1 otherwise.
struct Adjacency {
  std::vector<std::array<int, 3>> neighbour;
  std::vector<std::array<int, 3>> neighbour_slot;
  std::size_t non_manifold_edges = 0;
};

Adjacency adjacency(const std::vector<std::array<int, 3>>& corners) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * corners.size());
  for (std::size_t t = 0; t < corners.size(); ++t)
    for (int slot = 0; slot < 3; ++slot)
      uses.push_back(
          {edge_key(corners[t][slot], corners[t][(slot + 1) % 3]), static_cast<int>(t), slot});
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) {
    return a.key != b.key ? a.key < b.key : a.triangle < b.triangle;
  });
  Adjacency result;
  result.neighbour.assign(corners.size(), {-1, -1, -1});
  result.neighbour_slot.assign(corners.size(), {-1, -1, -1});
  for (std::size_t begin = 0; begin < uses.size();) {
    std::size_t end = begin;
    while (end < uses.size() && uses[end].key == uses[begin].key) ++end;
    if (end - begin == 2) {
      const EdgeUse& a = uses[begin];
      const EdgeUse& b = uses[begin + 1];
      result.neighbour[a.triangle][a.slot] = b.triangle;
      result.neighbour_slot[a.triangle][a.slot] = b.slot;
      result.neighbour[b.triangle][b.slot] = a.triangle;
      result.neighbour_slot[b.triangle][b.slot] = a.slot;
    } else if (end - begin > 2) {
      ++result.non_manifold_edges;
    }
    begin = end;
  }
  return result;
}

// true when triangle u runs the edge it shares with t (slot of t) the same way t does.
bool same_direction(const std::vector<std::array<int, 3>>& corners, int t, int slot, int u,
                    int u_slot) {
  return corners[t][slot] == corners[u][u_slot];
}

// === Orientation of components

// turns triangles so that each edge-connected component is consistently oriented (when it
// can be), closed components outward (positive signed volume) and open ones as most of
// their triangles were in the file; marks the triangles of closed components as solid.
void orient_components(std::vector<std::array<int, 3>>& corners,
                       const std::vector<RationalPoint3>& points, const Adjacency& adjacent,
                       std::vector<char>& solid, RepairReport& repairs) {
  const std::size_t count = corners.size();
  std::vector<signed char> flip(count, -1);
  solid.assign(count, 0);
  std::vector<int> component;
  for (std::size_t seed = 0; seed < count; ++seed) {
    if (flip[seed] != -1) continue;
    // Breadth-first over manifold edges: a neighbour running the shared edge the same way
    // must be turned relative to this triangle.
    component.assign(1, static_cast<int>(seed));
    flip[seed] = 0;
    bool consistent = true, closed = true;
    for (std::size_t k = 0; k < component.size(); ++k) {
      const int t = component[k];
      for (int slot = 0; slot < 3; ++slot) {
        const int u = adjacent.neighbour[t][slot];
        if (u < 0) {
          closed = false;
          continue;
        }
        const signed char wanted = static_cast<signed char>(
            flip[t] ^
            (same_direction(corners, t, slot, u, adjacent.neighbour_slot[t][slot]) ? 1 : 0));
        if (flip[u] == -1) {
          flip[u] = wanted;
          component.push_back(u);
        } else if (flip[u] != wanted) {
          consistent = false;
        }
      }
    }
    if (!consistent) {  // non-orientable: left as in the file
      for (int t : component) flip[t] = 0;
      closed = false;
    }
    std::size_t flipped = 0;
    for (int t : component) flipped += static_cast<std::size_t>(flip[t]);
    bool turn_all = 2 * flipped > component.size();
    if (closed) {
      // 6 V = sum over triangles of a . (b x c), exactly; outward when positive.
      Rational six_volume = 0;
      for (int t : component) {
        const auto& a = points[corners[t][0]];
        const auto& b = points[corners[t][flip[t] ? 2 : 1]];
        const auto& c = points[corners[t][flip[t] ? 1 : 2]];
        six_volume += a.x() * (b.y() * c.z() - b.z() * c.y()) -
                      a.y() * (b.x() * c.z() - b.z() * c.x()) +
                      a.z() * (b.x() * c.y() - b.y() * c.x());
      }
      turn_all = CGAL::is_negative(six_volume);
      ++repairs.closed_components;
    } else {
      ++repairs.open_components;
    }
    bool any = false;
    for (int t : component) {
      if (turn_all) flip[t] = static_cast<signed char>(1 - flip[t]);
      if (flip[t]) {
        std::swap(corners[t][1], corners[t][2]);
        any = true;
      }
      solid[t] = closed ? 1 : 0;
    }
    if (any) ++repairs.components_reoriented;
  }
}

// === Planes

// A triangle's plane in a canonical form: the coefficients of RationalPlane3(a, b, c)
// divided by the absolute value of the first non-zero normal component, so that two
// triangles lie in one plane and face the same way exactly when their keys are equal.
struct PlaneKey {
  std::array<Rational, 4> coefficients;
  int material;
  bool solid;

  bool operator==(const PlaneKey& other) const {
    return material == other.material && solid == other.solid && coefficients == other.coefficients;
  }
};

struct PlaneKeyHash {
  std::size_t operator()(const PlaneKey& key) const {
    std::size_t hash = std::hash<int>()(key.material) * 2 + (key.solid ? 1 : 0);
    for (const auto& x : key.coefficients)
      hash = hash * 1000003u ^ std::hash<double>()(CGAL::to_double(x));
    return hash;
  }
};

PlaneKey plane_key(const RationalPlane3& plane, int material, bool solid) {
  PlaneKey key{{plane.a(), plane.b(), plane.c(), plane.d()}, material, solid};
  Rational scale = 0;
  for (int k = 0; k < 3 && CGAL::is_zero(scale); ++k) scale = CGAL::abs(key.coefficients[k]);
  for (auto& x : key.coefficients) x /= scale;
  return key;
}

// === Rings

// removes ring points equal to the next one or between two collinear neighbours.
void drop_collinear(std::vector<Point3>& ring) {
  const auto straight = [](const Point3& a, const Point3& b, const Point3& c) {
    return a == b || b == c || CGAL::collinear(a, b, c);
  };
  std::vector<Point3> kept;
  for (const auto& p : ring) {
    kept.push_back(p);
    while (kept.size() >= 3 &&
           straight(kept[kept.size() - 3], kept[kept.size() - 2], kept[kept.size() - 1]))
      kept.erase(kept.end() - 2);
  }
  for (bool changed = true; changed && kept.size() >= 3;) {
    changed = false;
    if (straight(kept[kept.size() - 2], kept.back(), kept.front())) {
      kept.pop_back();
      changed = true;
    } else if (straight(kept.back(), kept[0], kept[1])) {
      kept.erase(kept.begin());
      changed = true;
    }
  }
  if (kept.size() < 3) kept.clear();
  ring = std::move(kept);
}

// The triangles of one plane (and material), united exactly in the plane's projection.
class PlaneUnion {
 public:
  PlaneUnion(const RationalPlane3& plane, const std::vector<RationalPoint3>& points,
             const std::vector<Point3>& epeck_points)
      : plane_(plane),
        projection_(plane.orthogonal_vector()),
        points_(points),
        epeck_points_(epeck_points) {}

  // returns the faces covering the triangles (corners counter-clockwise seen from the
  // plane's positive side), each with the number of triangles inside it.
  std::vector<PlanarFace> faces(const std::vector<std::array<int, 3>>& triangles) {
    if (auto tiled = tiled_faces(triangles)) return in_order(std::move(*tiled));
    std::vector<Polygon2> polygons;
    polygons.reserve(triangles.size());
    for (const auto& t : triangles) {
      Polygon2 polygon;
      for (int v : t) polygon.push_back(project(v));
      polygons.push_back(std::move(polygon));
    }
    PolygonSet2 set;
    set.join(polygons.begin(), polygons.end());
    std::vector<PolygonWithHoles2> pieces;
    set.polygons_with_holes(std::back_inserter(pieces));

    // Where triangles overlapped, the union covers the overlap once: less area.
    Rational triangles_area = 0, union_area = 0;
    for (const auto& polygon : polygons) triangles_area += exact_value(polygon.area());
    for (const auto& piece : pieces) {
      union_area += exact_value(piece.outer_boundary().area());
      for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole)
        union_area += exact_value(hole->area());
    }
    overlapped_ = union_area != triangles_area;

    std::vector<PlanarFace> result;
    for (const auto& piece : pieces) {
      PlanarFace face;
      face.plane = from_exact<Plane3>(plane_);
      face.outer = lift(piece.outer_boundary());
      for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole) {
        auto ring = lift(*hole);
        if (!ring.empty()) face.holes.push_back(std::move(ring));
      }
      if (!face.outer.empty()) result.push_back(std::move(face));
    }
    // Count each triangle in the piece holding its centroid (inside the outer ring, outside
    // the holes).
    if (result.size() == 1) {
      result[0].triangles = triangles.size();
    } else {
      for (const auto& polygon : polygons) {
        const Point2 centroid = CGAL::centroid(polygon[0], polygon[1], polygon[2]);
        for (std::size_t k = 0; k < pieces.size() && k < result.size(); ++k) {
          int winding = detail::winding_number(pieces[k].outer_boundary().container(), centroid);
          for (auto hole = pieces[k].holes_begin(); hole != pieces[k].holes_end(); ++hole)
            winding += detail::winding_number(hole->container(), centroid);
          if (winding != 0) {
            ++result[k].triangles;
            break;
          }
        }
      }
    }
    return in_order(std::move(result));
  }

 private:
  // returns faces ordered by their outer rings' lexicographically smallest points,
  // whichever way they were found (pieces of a union that touch at their smallest point
  // keep the union's order).
  static std::vector<PlanarFace> in_order(std::vector<PlanarFace> faces) {
    const auto smallest = [](const PlanarFace& face) {
      return *std::min_element(face.outer.begin(), face.outer.end(), point_less);
    };
    std::stable_sort(faces.begin(), faces.end(), [&](const PlanarFace& a, const PlanarFace& b) {
      return point_less(smallest(a), smallest(b));
    });
    return faces;
  }

  // the faces when the triangles tile them edge to edge (edge_rings.h), else nothing.
  std::optional<std::vector<PlanarFace>> tiled_faces(
      const std::vector<std::array<int, 3>>& triangles) const {
    std::unordered_map<int, int> local;
    std::vector<int> global;
    std::vector<Point2> projected;
    std::vector<std::array<int, 3>> renumbered;
    for (const auto& t : triangles) {
      std::array<int, 3> r;
      for (int k = 0; k < 3; ++k) {
        const auto [it, inserted] = local.emplace(t[k], static_cast<int>(global.size()));
        if (inserted) {
          const RationalPoint3& p = points_[t[k]];
          global.push_back(t[k]);
          projected.push_back(
              point_from<Point2>(RationalPoint2(p[projection_.first], p[projection_.second])));
        }
        r[k] = it->second;
      }
      renumbered.push_back(r);
    }
    const auto found = detail::edge_ring_faces(renumbered, projected);
    if (!found) return std::nullopt;
    const auto lift_ring = [&](const std::vector<int>& ring) {
      std::vector<Point3> lifted;
      for (int v : ring) lifted.push_back(epeck_points_[global[v]]);
      drop_collinear(lifted);
      return lifted;
    };
    std::vector<PlanarFace> result;
    for (const auto& tiled : *found) {
      PlanarFace face;
      face.plane = from_exact<Plane3>(plane_);
      face.outer = lift_ring(tiled.outer);
      for (const auto& hole : tiled.holes) {
        auto ring = lift_ring(hole);
        if (!ring.empty()) face.holes.push_back(std::move(ring));
      }
      face.triangles = tiled.triangles;
      if (!face.outer.empty()) result.push_back(std::move(face));
    }
    return result;
  }

  Point2 project(int v) {
    const RationalPoint3& p = points_[v];
    RationalPoint2 q(p[projection_.first], p[projection_.second]);
    const auto [it, inserted] = lifted_.emplace(q, v);
    if (!inserted && it->second != v) it->second = std::min(it->second, v);
    return point_from<Point2>(std::move(q));
  }

  // returns the ring in space: a projected point of a triangle corner is that corner; a
  // point the union made (where edges cross) is solved from the plane's equation.
  std::vector<Point3> lift(const Polygon2& polygon) const {
    std::vector<Point3> ring;
    for (const auto& q : polygon.container()) {
      const RationalPoint2& exact = exact_value(q);
      const auto found = lifted_.find(exact);
      if (found != lifted_.end()) {
        ring.push_back(epeck_points_[found->second]);
        continue;
      }
      const int axis = 3 - projection_.first - projection_.second;
      const std::array<Rational, 3> n = {plane_.a(), plane_.b(), plane_.c()};
      std::array<Rational, 3> p;
      p[projection_.first] = exact.x();
      p[projection_.second] = exact.y();
      p[axis] =
          -(plane_.d() + n[projection_.first] * exact.x() + n[projection_.second] * exact.y()) /
          n[axis];
      ring.push_back(point_from<Point3>(RationalPoint3(p[0], p[1], p[2])));
    }
    drop_collinear(ring);
    return ring;
  }

  RationalPlane3 plane_;
  Projection projection_;
  const std::vector<RationalPoint3>& points_;
  const std::vector<Point3>& epeck_points_;
  std::map<RationalPoint2, int> lifted_;
  bool overlapped_ = false;

 public:
  // true when some triangles overlapped (so the faces' area is less than theirs).
  bool overlapped() const { return overlapped_; }
};

PlanarFace triangle_face(const std::array<int, 3>& c, const RationalPlane3& plane,
                         const std::vector<Point3>& epeck_points) {
  PlanarFace face;
  face.plane = from_exact<Plane3>(plane);
  face.outer = {epeck_points[c[0]], epeck_points[c[1]], epeck_points[c[2]]};
  face.triangles = 1;
  return face;
}

}  // namespace

std::vector<PlanarFace> planar_faces(const TriangleSoup& soup, RepairReport& repairs) {
  // Merge equal points; keep only the points triangles use.
  const std::vector<int> first = first_equal_points(soup.points, repairs.duplicate_vertices_merged);
  std::vector<int> index(soup.points.size(), -1);
  std::vector<RationalPoint3> points;
  std::vector<Point3> epeck_points;
  const auto vertex = [&](int i) {
    const int f = first[i];
    if (index[f] < 0) {
      index[f] = static_cast<int>(points.size());
      points.push_back(soup.points[f]);
      epeck_points.push_back(point_from<Point3>(soup.points[f]));
    }
    return index[f];
  };

  // Drop triangles with fewer than 3 distinct points or collinear points.
  std::vector<std::array<int, 3>> corners;
  std::vector<int> materials;
  for (std::size_t t = 0; t < soup.corners.size(); ++t) {
    const std::array<int, 3> c = {vertex(soup.corners[t][0]), vertex(soup.corners[t][1]),
                                  vertex(soup.corners[t][2])};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0] ||
        CGAL::collinear(epeck_points[c[0]], epeck_points[c[1]], epeck_points[c[2]])) {
      ++repairs.degenerate_faces_dropped;
      continue;
    }
    corners.push_back(c);
    materials.push_back(soup.materials[t]);
  }
  if (corners.empty()) return {};

  const Adjacency adjacent = adjacency(corners);
  repairs.non_manifold_edges += adjacent.non_manifold_edges;
  std::vector<char> solid;
  orient_components(corners, points, adjacent, solid, repairs);

  // Group the triangles by exact oriented plane, material and solidity, in the order of
  // each group's first triangle.
  std::unordered_map<PlaneKey, std::size_t, PlaneKeyHash> group_of;
  std::vector<RationalPlane3> planes;
  std::vector<std::vector<int>> groups;
  for (std::size_t t = 0; t < corners.size(); ++t) {
    RationalPlane3 plane(points[corners[t][0]], points[corners[t][1]], points[corners[t][2]]);
    const auto [it, inserted] =
        group_of.emplace(plane_key(plane, materials[t], solid[t] != 0), groups.size());
    if (inserted) {
      groups.emplace_back();
      planes.push_back(std::move(plane));
    }
    groups[it->second].push_back(static_cast<int>(t));
  }

  // One face per connected piece of each group's union: adjacent triangles (sharing an
  // edge or part of one) merge; the piece may be non-convex and have holes.
  std::vector<PlanarFace> faces;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const int t0 = groups[g].front();
    std::vector<PlanarFace> pieces;
    if (groups[g].size() == 1) {
      pieces.push_back(triangle_face(corners[t0], planes[g], epeck_points));
    } else {
      std::vector<std::array<int, 3>> triangles;
      for (int t : groups[g]) triangles.push_back(corners[t]);
      PlaneUnion plane_union(planes[g], points, epeck_points);
      pieces = plane_union.faces(triangles);
      if (plane_union.overlapped()) repairs.overlapping_faces += pieces.size();
    }
    for (auto& face : pieces) {
      face.material = materials[t0];
      face.solid = solid[t0] != 0;
      faces.push_back(std::move(face));
    }
  }
  return faces;
}

}  // namespace penumbra
