#include "mesh_parts.h"

#include <algorithm>
#include <sstream>

#include "penumbra/base/input_error.h"
#include "penumbra/geometry/convex_pieces.h"
#include "penumbra/geometry/geometry_error.h"
#include "penumbra/geometry/point_order.h"

namespace penumbra::detail {
namespace {

// returns the part's convex hull when the part is a closed solid lying on it: every face is
// on the outer side of a closed, outward-oriented component and in the plane of a hull face,
// with the same orientation. A closed surface whose every face lies on the boundary of the
// hull of its points is that boundary, so the part is the convex solid itself.
std::optional<ConvexPolyhedron> convex_solid(const ModelPart& part) {
  std::vector<Point3> points;
  for (const PlanarFace& face : part.faces) {
    if (!face.solid || !face.holes.empty()) return std::nullopt;
    points.insert(points.end(), face.outer.begin(), face.outer.end());
  }
  // A point strictly outside one face's plane proves the part is not convex: for a small
  // part that is cheaper than the hull (a building of a few dozen points).
  if (points.size() <= 64)
    for (const PlanarFace& face : part.faces)
      for (const Point3& p : points)
        if (face.plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE) return std::nullopt;
  std::optional<ConvexPolyhedron> hull;
  try {
    hull = ConvexPolyhedron::hull(points);
  } catch (const GeometryError&) {
    return std::nullopt;  // flat: not a solid
  }
  for (const PlanarFace& face : part.faces) {
    const bool on_hull =
        std::any_of(hull->faces().begin(), hull->faces().end(), [&](const Face& h) {
          return h.plane == face.plane &&
                 CGAL::is_positive(h.normal() * face.plane.orthogonal_vector());
        });
    if (!on_hull) return std::nullopt;
  }
  return hull;
}

// The MeshFace on plane's positive side with the given rings (counter-clockwise outer,
// clockwise holes, seen from that side) made of pieces (part, index and the pieces' object
// numbers are filled in later).
MeshFace mesh_face(const std::vector<ConvexPolyhedron>& pieces, const Plane3& plane,
                   const std::vector<Point3>& outer,
                   const std::vector<std::vector<Point3>>& holes) {
  MeshFace face;
  if (pieces.size() == 1) {
    // One convex piece: the face is the piece's on this side, frame and all.
    const auto& sides = pieces[0].faces();
    const Face& piece = sides[0].plane == plane ? sides[0] : sides[1];
    face.plane = piece.plane;
    face.frame = piece.frame;
    face.outer = piece.vertices;
    face.ring = piece.ring;
    face.area = piece.area;
    return face;
  }
  face.plane = plane;
  face.outer = outer;
  face.holes = holes;
  start_at_smallest(face.outer);
  for (auto& hole : face.holes) start_at_smallest(hole);
  std::sort(face.holes.begin(), face.holes.end(),
            [](const auto& a, const auto& b) { return point_less(a.front(), b.front()); });
  face.frame = FaceFrame(face.outer[0], face.outer[1] - face.outer[0], plane.orthogonal_vector());
  // The shoelace formula over every ring in the frame: holes run clockwise, so they subtract.
  Exact twice = 0;
  const auto add_ring = [&](const std::vector<Point3>& ring) {
    std::vector<Point2> q;
    for (const Point3& p : ring) q.push_back(face.frame.to_frame(p));
    for (std::size_t k = 0; k < q.size(); ++k) {
      const Point2& a = q[k];
      const Point2& b = q[(k + 1) % q.size()];
      twice += a.x() * b.y() - b.x() * a.y();
    }
    return q;
  };
  face.ring = add_ring(face.outer);
  for (const auto& hole : face.holes) add_ring(hole);
  face.area = twice / 2;
  return face;
}

std::vector<Point3> reversed(const std::vector<Point3>& ring) {
  return {ring.rbegin(), ring.rend()};
}

}  // namespace

MeshPartObjects mesh_part_objects(const ModelPart& part, const std::string& file) {
  MeshPartObjects objects;
  objects.convex = convex_solid(part);
  if (objects.convex) return objects;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const PlanarFace& face = part.faces[f];
    std::vector<ConvexPolyhedron> pieces;
    try {
      for (const auto& cycle : convex_pieces(face.plane, face.outer, face.holes))
        pieces.push_back(ConvexPolyhedron::flat_polygon(cycle));
    } catch (const GeometryError& e) {
      throw InputError(file, "part " + part.name + ", face " + std::to_string(f),
                       std::string("the face cannot be cut into convex pieces: ") + e.what());
    }
    objects.mesh_faces.push_back(mesh_face(pieces, face.plane, face.outer, face.holes));
    // An open surface receives on both sides: the back is the next face.
    if (!face.solid) {
      std::vector<std::vector<Point3>> holes;
      for (const auto& hole : face.holes) holes.push_back(reversed(hole));
      objects.mesh_faces.push_back(
          mesh_face(pieces, face.plane.opposite(), reversed(face.outer), holes));
    }
    objects.faces.push_back(std::move(pieces));
  }
  return objects;
}

void add_mesh_part(Scene& scene, const Object& base, const ModelPart& part,
                   MeshPartObjects objects) {
  if (objects.convex) {
    Object object = base;
    object.solid = std::move(*objects.convex);
    scene.objects.push_back(std::move(object));
    return;
  }
  std::size_t piece_number = 0, face_number = 0;
  const auto add = [&](std::vector<std::pair<std::size_t, std::size_t>> pieces) {
    for (const auto& [object, face] : pieces)
      scene.objects[object].mesh_faces[face] = scene.mesh_faces.size();
    MeshFace& face = objects.mesh_faces[face_number];
    face.part = base.name;
    face.index = face_number++;
    face.pieces = std::move(pieces);
    scene.mesh_faces.push_back(std::move(face));
  };
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const PlanarFace& planar = part.faces[f];
    std::vector<std::pair<std::size_t, std::size_t>> front, back;
    for (ConvexPolyhedron& solid : objects.faces[f]) {
      const std::size_t own = solid.faces()[0].plane == planar.plane ? 0 : 1;
      Object piece = base;
      piece.name = base.name + "#" + std::to_string(piece_number++);
      piece.part = base.name;
      piece.solid = std::move(solid);
      piece.mesh_faces.assign(2, kNoMeshFace);
      front.push_back({scene.objects.size(), own});
      back.push_back({scene.objects.size(), 1 - own});
      scene.objects.push_back(std::move(piece));
    }
    add(std::move(front));
    if (!planar.solid) add(std::move(back));
  }
}

std::string repair_summary(const RepairReport& repairs) {
  std::ostringstream out;
  const auto item = [&](std::size_t count, const char* what) {
    if (count == 0) return;
    out << (out.tellp() > 0 ? ", " : "repaired: ") << count << ' ' << what;
  };
  item(repairs.degenerate_faces_dropped, "degenerate triangles dropped");
  item(repairs.non_surface_primitives_ignored, "points and lines ignored");
  item(repairs.components_reoriented, "components reoriented");
  item(repairs.overlapping_faces, "faces with overlapping triangles");
  item(repairs.non_manifold_edges, "non-manifold edges");
  return out.str();
}

}  // namespace penumbra::detail
