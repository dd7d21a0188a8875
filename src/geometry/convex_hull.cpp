// ConvexPolyhedron::hull: CGAL's convex_hull_3, then coplanar triangles merged into
// maximal convex faces. Kept in its own file: the hull headers are heavy.
//
// Points given as doubles (the usual case: every coordinate of a scene file is a double)
// take the fast path: the hull of the inexact-constructions kernel, whose predicates are
// exact (CGAL's filtered predicates on the doubles, exact arithmetic when a filter fails, and
// a hull traits class that represents planes by their three points, so no constructed value
// decides anything). Adjacent hull triangles lie in one face exactly when the fourth point is
// coplanar with them (an exact orientation test); each face is walked along its boundary.
// Other points (rationals, from transformed meshes) take the exact-kernel path. Both give the
// same faces and the same canonical numbering.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>

#include "convex_hull_2.h"
#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/dyadic_plane.h"
#include "penumbra/geometry/geometry_error.h"
#include "small_hull.h"

namespace penumbra {
namespace {

using FastKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FastPoint = FastKernel::Point_3;

// throws unless some 4 of the points are not coplanar.
template <class Point>
void require_solid(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  std::size_t second = 1;
  while (second < n && points[second] == points[0]) ++second;
  std::size_t third = second + 1;
  while (third < n && CGAL::collinear(points[0], points[second], points[third])) ++third;
  std::size_t fourth = third + 1;
  while (fourth < n && CGAL::coplanar(points[0], points[second], points[third], points[fourth]))
    ++fourth;
  if (fourth >= n)
    throw GeometryError("a convex solid needs at least 4 points that are not coplanar");
}

// returns the points as doubles when every coordinate is one (its interval is a single
// value), or nothing.
std::optional<std::vector<FastPoint>> as_doubles(const std::vector<Point3>& points) {
  std::vector<FastPoint> doubles;
  doubles.reserve(points.size());
  for (const Point3& p : points) {
    const auto x = double_coordinates(p);
    if (!x) return std::nullopt;
    doubles.emplace_back((*x)[0], (*x)[1], (*x)[2]);
  }
  return doubles;
}

// The fast path: faces of the hull of points given as doubles, each a counter-clockwise
// cycle (seen from outside) of its extreme points.
std::vector<std::vector<Point3>> faces_of_double_hull(const std::vector<FastPoint>& points) {
  using Mesh = CGAL::Surface_mesh<FastPoint>;
  Mesh mesh;
  CGAL::convex_hull_3(points.begin(), points.end(), mesh);

  // Group the triangles by face: union of neighbours whose far corner is coplanar.
  std::vector<std::size_t> group(mesh.number_of_faces());
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&](std::size_t f) {
    while (group[f] != f) f = group[f] = group[group[f]];
    return f;
  };
  for (auto h : mesh.halfedges()) {
    const auto face = mesh.face(h), across = mesh.face(mesh.opposite(h));
    if (face >= across) continue;  // each edge once
    const FastPoint& a = mesh.point(mesh.source(h));
    const FastPoint& b = mesh.point(mesh.target(h));
    const FastPoint& c = mesh.point(mesh.target(mesh.next(h)));
    const FastPoint& d = mesh.point(mesh.target(mesh.next(mesh.opposite(h))));
    if (CGAL::orientation(a, b, c, d) == CGAL::COPLANAR) group[root(face)] = root(across);
  }

  // Each face's boundary: the halfedges whose opposite triangle is in another face, chained
  // from target to source (a convex face has one boundary cycle).
  std::map<std::size_t, std::map<Mesh::Vertex_index, Mesh::Halfedge_index>> boundary;
  for (auto h : mesh.halfedges())
    if (root(mesh.face(h)) != root(mesh.face(mesh.opposite(h))))
      boundary[root(mesh.face(h))][mesh.source(h)] = h;
  // One exact point per hull vertex, shared by the faces around it.
  std::map<Mesh::Vertex_index, Point3> exact;
  std::vector<std::vector<Point3>> faces;
  for (const auto& [face, edges] : boundary) {
    std::vector<Mesh::Vertex_index> cycle;
    auto h = edges.begin()->second;
    do {
      cycle.push_back(mesh.source(h));
      h = edges.at(mesh.target(h));
    } while (h != edges.begin()->second);
    // Drop the vertices that are not extreme (between two collinear edges), exactly.
    for (bool dropped = true; dropped && cycle.size() > 3;) {
      dropped = false;
      for (std::size_t k = 0; k < cycle.size() && cycle.size() > 3; ++k) {
        const std::size_t n = cycle.size();
        if (CGAL::collinear(mesh.point(cycle[(k + n - 1) % n]), mesh.point(cycle[k]),
                            mesh.point(cycle[(k + 1) % n]))) {
          cycle.erase(cycle.begin() + static_cast<std::ptrdiff_t>(k));
          dropped = true;
        }
      }
    }
    std::vector<Point3> points_of_face;
    for (const auto v : cycle) {
      auto [at, inserted] = exact.try_emplace(v);
      if (inserted) at->second = Point3(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
      points_of_face.push_back(at->second);
    }
    faces.push_back(std::move(points_of_face));
  }
  return faces;
}

// The exact path: CGAL's hull in the exact kernel, triangles grouped by outward normal
// direction (on a convex polytope two triangles share a direction exactly when they lie
// in the same face), each face the 2D hull of its triangles' corners.
std::vector<std::vector<Point3>> faces_of_exact_hull(const std::vector<Point3>& points) {
  CGAL::Surface_mesh<Point3> mesh;
  CGAL::convex_hull_3(points.begin(), points.end(), mesh);
  struct Triangle {
    Vector3 normal;
    std::array<Point3, 3> corners;
  };
  std::vector<Triangle> triangles;
  for (auto f : mesh.faces()) {
    Triangle t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t.corners[k++] = mesh.point(v);
    t.normal = CGAL::cross_product(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end(), [](const Triangle& a, const Triangle& b) {
    return detail::direction_less(a.normal, b.normal);
  });
  std::vector<std::vector<Point3>> face_cycles;
  for (std::size_t first = 0; first < triangles.size();) {
    std::size_t last = first + 1;
    while (last < triangles.size() &&
           !detail::direction_less(triangles[first].normal, triangles[last].normal))
      ++last;
    std::vector<Point3> corners;
    for (std::size_t t = first; t < last; ++t)
      corners.insert(corners.end(), triangles[t].corners.begin(), triangles[t].corners.end());
    const Vector3& normal = triangles[first].normal;
    const FaceFrame frame(corners[0], detail::in_plane_direction(normal), normal);
    std::vector<Point2> flat;
    for (const Point3& p : corners) flat.push_back(frame.to_frame(p));
    std::vector<Point3> cycle;
    for (int index : detail::convex_hull_2(flat)) cycle.push_back(corners[index]);
    face_cycles.push_back(std::move(cycle));
    first = last;
  }
  return face_cycles;
}

// The faces of a few distinct points given as doubles (small_hull.h).
std::vector<std::vector<Point3>> faces_of_small_hull(const std::vector<FastPoint>& points) {
  std::vector<std::array<double, 3>> coordinates;
  for (const FastPoint& p : points) coordinates.push_back({p.x(), p.y(), p.z()});
  std::vector<std::optional<Point3>> exact(points.size());  // one per vertex, shared
  std::vector<std::vector<Point3>> faces;
  for (const std::vector<std::size_t>& cycle : detail::small_hull(coordinates)) {
    std::vector<Point3> face;
    for (std::size_t v : cycle) {
      if (!exact[v]) exact[v].emplace(points[v].x(), points[v].y(), points[v].z());
      face.push_back(*exact[v]);
    }
    faces.push_back(std::move(face));
  }
  return faces;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::hull(const std::vector<Point3>& points) {
  if (auto doubles = as_doubles(points)) {
    require_solid(*doubles);
    std::sort(doubles->begin(), doubles->end());
    doubles->erase(std::unique(doubles->begin(), doubles->end()), doubles->end());
    if (doubles->size() <= detail::kSmallHullPoints)
      return from_faces(faces_of_small_hull(*doubles), false);
    return from_faces(faces_of_double_hull(*doubles), false);
  }
  require_solid(points);
  return from_faces(faces_of_exact_hull(points), false);
}

}  // namespace penumbra
