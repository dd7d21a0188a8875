// ConvexPolyhedron::hull: CGAL's convex_hull_3, then coplanar triangles merged
// into maximal convex faces. Kept in its own file: the hull headers are heavy.

#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>

#include "convex_hull_2.h"
#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/geometry_error.h"

namespace penumbra {
namespace {

// throws unless some 4 of the points are not coplanar.
void require_solid(const std::vector<Point3>& points) {
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

}  // namespace

ConvexPolyhedron ConvexPolyhedron::hull(const std::vector<Point3>& points) {
  require_solid(points);
  CGAL::Surface_mesh<Point3> mesh;
  CGAL::convex_hull_3(points.begin(), points.end(), mesh);

  // Group the hull's triangles by outward normal direction: on a convex polytope
  // two triangles share a direction exactly when they lie in the same face.
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
    // The face is the 2D hull of its triangles' corners, counter-clockwise in a
    // frame whose u x v is the outward normal.
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
  return from_faces(std::move(face_cycles), false);
}

}  // namespace penumbra
