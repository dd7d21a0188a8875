#pragma once
// The exact model's solid: a convex polyhedron with faces as maximal convex
// polygons (coplanar hull triangles merged exactly), counter-clockwise seen from
// outside, with exact outward planes and 2D frames (DESIGN.md, "Conventions").
//
// Numbering is canonical, independent of the order of the input points
// (docs/geometry.md): vertices in lexicographic (x, y, z) order; faces in
// lexicographic order of their unit outward normal (x, then y, then z); each face's
// vertex cycle starts at its lexicographically smallest vertex.

#include <cstddef>
#include <vector>

#include "penumbra/geometry/face_frame.h"
#include "penumbra/geometry/kernel.h"

namespace penumbra {

struct Face {
  std::vector<Point3> vertices;  // counter-clockwise seen from outside, no three collinear
  std::vector<int> vertex_ids;   // indices into ConvexPolyhedron::vertices()
  std::vector<int> neighbours;   // neighbours[k]: the face across edge (k, k+1)
  Plane3 plane;                  // F(S, Q) = n.Q + d, positive on the outside (Nishita eq. 3)
  FaceFrame frame;               // origin = vertices[0], u along the first edge
  std::vector<Point2> ring;      // the vertices in the frame (to_frame), exact
  Exact area;                    // the ring's area in frame units (world area = area |u| |v|)

  Vector3 normal() const { return plane.orthogonal_vector(); }
};

class ConvexPolyhedron {
 public:
  // builds the convex hull of points (duplicates, collinear and coplanar members
  // allowed). Throws GeometryError when fewer than 4 of them are non-coplanar.
  static ConvexPolyhedron hull(const std::vector<Point3>& points);

  // builds a two-sided planar convex polygon: a flat solid with two opposite faces
  // on the same plane. The points must be coplanar, not all collinear, and in
  // convex position along the given cycle (collinear and repeated consecutive
  // points allowed). Throws GeometryError otherwise.
  static ConvexPolyhedron flat_polygon(const std::vector<Point3>& cycle);

  const std::vector<Point3>& vertices() const { return vertices_; }
  const std::vector<Face>& faces() const { return faces_; }
  // true for a two-sided polygon (two faces, zero volume).
  bool is_flat() const { return flat_; }

  // the axis-aligned bounding box, rounded outward to doubles.
  CGAL::Bbox_3 bbox() const;

  // returns the side of p: ON_BOUNDED_SIDE (interior), ON_BOUNDARY or
  // ON_UNBOUNDED_SIDE. A flat polygon has no interior.
  CGAL::Bounded_side bounded_side(const Point3& p) const;

 private:
  // orders vertices and faces canonically and fills ids, neighbours and frames.
  static ConvexPolyhedron from_faces(std::vector<std::vector<Point3>> face_cycles, bool flat);

  std::vector<Point3> vertices_;
  std::vector<Face> faces_;
  bool flat_ = false;
};

}  // namespace penumbra
