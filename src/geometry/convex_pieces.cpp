#include "penumbra/geometry/convex_pieces.h"
#include "penumbra/geometry/point_order.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <deque>
#include <numeric>

namespace penumbra {
namespace {

struct FaceInfo {
  int nesting = -1;  // how many rings separate the face from the unbounded one
  int piece = -1;    // the piece (index into the pieces' cycles) holding the triangle
};

struct VertexInfo {
  int point = 0;  // the ring point, 1-based; 0 for none (a vertex where constraints cross)
};

// A triangulation element with a creation stamp. CGAL's containers then order and hash
// handles by the stamps instead of by address (CGAL/Time_stamper.h): among equal choices
// (cocircular points, everywhere in rectilinear CAD faces) the triangulation's flips
// follow the order of its faces, which by address changed with the heap from run to run
// and thread to thread, and the pieces with them.
template <class Base>
class Stamped : public Base {
 public:
  using Has_timestamp = CGAL::Tag_true;
  template <class Tds2>
  struct Rebind_TDS {
    using Other = Stamped<typename Base::template Rebind_TDS<Tds2>::Other>;
  };
  using Base::Base;
  std::size_t time_stamp() const { return stamp_; }
  void set_time_stamp(const std::size_t& stamp) { stamp_ = stamp; }

 private:
  std::size_t stamp_ = std::size_t(-1);
};

using VertexBase = Stamped<CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>>;
using FaceBase = Stamped<CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Rings may touch (a hole's vertex on the outer ring's edge): the constraint is split there,
// at a point that exists, so exact intersections cost nothing extra.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_intersections_tag>;
using Vertex = Cdt::Vertex_handle;

// The plane seen along the axis k where the normal is largest: (coordinate k+1, k+2), swapped
// when the normal's k-th component is negative, so that counter-clockwise seen from the
// positive side stays counter-clockwise.
struct Projection {
  int axis;
  bool swap;

  explicit Projection(const Vector3& normal) {
    axis = 0;
    for (int k = 1; k < 3; ++k)
      if (CGAL::abs(normal[k]) > CGAL::abs(normal[axis])) axis = k;
    swap = CGAL::is_negative(normal[axis]);
  }
  Point2 operator()(const Point3& p) const {
    const Exact& a = p[(axis + 1) % 3];
    const Exact& b = p[(axis + 2) % 3];
    return swap ? Point2(b, a) : Point2(a, b);
  }
};

// marks each finite face with its nesting depth: 0 outside the outer ring, 1 inside it, 2 in
// a hole (the usual flood fill across constrained edges).
void mark_nesting(Cdt& cdt) {
  std::deque<std::pair<Cdt::Face_handle, int>> queue{{cdt.infinite_face(), 0}};
  while (!queue.empty()) {
    const auto [face, level] = queue.front();
    queue.pop_front();
    if (face->info().nesting != -1) continue;
    face->info().nesting = level;
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle next = face->neighbor(i);
      if (next->info().nesting != -1) continue;
      if (cdt.is_constrained({face, i}))
        queue.emplace_back(next, level + 1);
      else
        queue.emplace_front(next, level);
    }
  }
}

std::size_t position(const std::vector<Vertex>& cycle, Vertex v) {
  return static_cast<std::size_t>(std::find(cycle.begin(), cycle.end(), v) - cycle.begin());
}

// merges piece b into piece a across their shared diagonal pq (a runs p -> q, b runs q -> p)
// when the union is convex; returns whether it did.
bool merge_if_convex(std::vector<Vertex>& a, std::vector<Vertex>& b, Vertex p, Vertex q) {
  const std::size_t na = a.size(), nb = b.size();
  const std::size_t ap = position(a, p), bq = position(b, q);
  const std::size_t bp = (bq + 1) % nb;
  const Vertex a_before_p = a[(ap + na - 1) % na], a_after_q = a[(ap + 2) % na];
  const Vertex b_after_p = b[(bp + 1) % nb], b_before_q = b[(bq + nb - 1) % nb];
  if (CGAL::orientation(a_before_p->point(), p->point(), b_after_p->point()) == CGAL::RIGHT_TURN ||
      CGAL::orientation(b_before_q->point(), q->point(), a_after_q->point()) == CGAL::RIGHT_TURN)
    return false;
  // a from q round to p, then b strictly between p and q.
  std::vector<Vertex> merged;
  for (std::size_t k = 0; k < na; ++k) merged.push_back(a[(ap + 1 + k) % na]);
  for (std::size_t k = 1; k + 1 < nb; ++k) merged.push_back(b[(bp + k) % nb]);
  a = std::move(merged);
  b.clear();
  return true;
}

}  // namespace

std::vector<std::vector<Point3>> convex_pieces(const Plane3& plane,
                                               const std::vector<Point3>& outer,
                                               const std::vector<std::vector<Point3>>& holes) {
  // The triangulation depends on the order points are inserted in (cocircular points): each
  // ring from its lexicographically smallest point, holes in the order of those points.
  std::vector<std::vector<Point3>> rings{outer};
  rings.insert(rings.end(), holes.begin(), holes.end());
  for (auto& ring : rings) start_at_smallest(ring);
  std::sort(rings.begin() + 1, rings.end(),
            [](const auto& a, const auto& b) { return point_less(a.front(), b.front()); });
  const Projection project(plane.orthogonal_vector());
  std::vector<Point3> points;
  Cdt cdt;
  const auto add_ring = [&](const std::vector<Point3>& ring) {
    std::vector<Vertex> vertices;
    for (const Point3& p : ring) vertices.push_back(cdt.insert(project(p)));
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vertex v = vertices[k];
      if (v->info().point == 0) {
        points.push_back(ring[k]);
        v->info().point = static_cast<int>(points.size());
      }
    }
    for (std::size_t k = 0; k < vertices.size(); ++k)
      if (vertices[k] != vertices[(k + 1) % vertices.size()])
        cdt.insert_constraint(vertices[k], vertices[(k + 1) % vertices.size()]);
  };
  for (const auto& ring : rings) add_ring(ring);
  mark_nesting(cdt);

  // Every triangle inside starts as a piece of its own.
  std::vector<std::vector<Vertex>> pieces;
  for (auto face : cdt.finite_face_handles()) {
    if (face->info().nesting % 2 != 1) continue;
    face->info().piece = static_cast<int>(pieces.size());
    pieces.push_back({face->vertex(0), face->vertex(1), face->vertex(2)});
  }
  std::vector<int> owner(pieces.size());
  std::iota(owner.begin(), owner.end(), 0);
  const auto find = [&](int k) {
    while (owner[k] != k) k = owner[k] = owner[owner[k]];
    return k;
  };
  for (const auto& edge : cdt.finite_edges()) {
    const auto [face, i] = edge;
    const auto other = face->neighbor(i);
    if (cdt.is_constrained(edge) || face->info().piece < 0 || other->info().piece < 0) continue;
    // In face (counter-clockwise) the edge runs from vertex ccw(i) to vertex cw(i).
    const Vertex p = face->vertex(Cdt::ccw(i)), q = face->vertex(Cdt::cw(i));
    const int a = find(face->info().piece), b = find(other->info().piece);
    if (merge_if_convex(pieces[a], pieces[b], p, q)) owner[b] = a;
  }

  // Back to the plane: a vertex the triangulation added (where rings touch inside an edge)
  // is lifted onto the plane exactly.
  const Vector3 n = plane.orthogonal_vector();
  const auto lift = [&](Vertex v) -> Point3 {
    if (v->info().point > 0) return points[v->info().point - 1];
    const Point2& q = v->point();
    const Exact a = project.swap ? q.y() : q.x();
    const Exact b = project.swap ? q.x() : q.y();
    const int i = (project.axis + 1) % 3, j = (project.axis + 2) % 3;
    Exact c[3];
    c[i] = a;
    c[j] = b;
    c[project.axis] = -(n[i] * a + n[j] * b + plane.d()) / n[project.axis];
    return Point3(c[0], c[1], c[2]);
  };
  std::vector<std::vector<Point3>> result;
  for (const auto& piece : pieces) {
    if (piece.empty()) continue;
    std::vector<Point3> cycle;
    for (Vertex v : piece) cycle.push_back(lift(v));
    result.push_back(std::move(cycle));
  }
  return result;
}

}  // namespace penumbra
