#include "penumbra/shadow/area_volumes.h"

#include <algorithm>
#include <stdexcept>

#include "penumbra/shadow/contour.h"

namespace penumbra {
namespace {

// The signs of a set of points against a plane: whether some lie strictly on each side.
struct Sides {
  bool positive = false, negative = false;
};

Sides sides_of(const Point3& a, const Point3& b, const Point3& c,
               const std::vector<Point3>& points) {
  Sides sides;
  for (const Point3& x : points) {
    const CGAL::Orientation o = CGAL::orientation(a, b, c, x);
    sides.positive = sides.positive || o == CGAL::POSITIVE;
    sides.negative = sides.negative || o == CGAL::NEGATIVE;
    if (sides.positive && sides.negative) break;
  }
  return sides;
}

// adds the plane through a, b, c when it separates solid (the points v) from the source
// (the points q), oriented with v on its closed negative side.
void add_if_separating(const Point3& a, const Point3& b, const Point3& c,
                       const std::vector<Point3>& v, const std::vector<Point3>& q,
                       std::vector<Plane3>& planes) {
  if (CGAL::collinear(a, b, c)) return;
  const Sides solid = sides_of(a, b, c, v);
  if (solid.positive && solid.negative) return;
  const Sides source = sides_of(a, b, c, q);
  if (source.positive && source.negative) return;
  // Both on the plane: no side to tell (the caller excludes coplanar pairs).
  const bool solid_on = !solid.positive && !solid.negative;
  const bool source_on = !source.positive && !source.negative;
  if (solid_on && source_on) return;
  // The plane separates when the two sets have no strict side in common.
  if ((solid.positive && source.positive) || (solid.negative && source.negative)) return;
  const bool flip = solid.positive || source.negative;
  const Plane3 plane = flip ? Plane3(a, c, b) : Plane3(a, b, c);
  if (std::find(planes.begin(), planes.end(), plane) == planes.end()) planes.push_back(plane);
}

// returns true when the closed segment ab meets the closed solid.
bool segment_meets(const ConvexPolyhedron& solid, const Point3& a, const Point3& b) {
  if (a == b) return solid.bounded_side(a) != CGAL::ON_UNBOUNDED_SIDE;
  const auto inside = line_in_solid(solid, a, b);
  return inside && inside->first <= 1 && inside->second >= 0;
}

}  // namespace

bool polygon_meets_solid(const std::vector<Point3>& source, const ConvexPolyhedron& solid) {
  // A face's plane with the whole polygon strictly outside, or the polygon's plane with the
  // whole solid strictly on one side: apart (the usual case, predicates only).
  for (const Face& face : solid.faces())
    if (std::all_of(source.begin(), source.end(),
                    [&](const Point3& q) { return turned_toward(face, q); }))
      return false;
  const Sides across = sides_of(source[0], source[1], source[2], solid.vertices());
  if (source.size() >= 3 && !(across.positive && across.negative) &&
      std::none_of(solid.vertices().begin(), solid.vertices().end(), [&](const Point3& v) {
        return CGAL::orientation(source[0], source[1], source[2], v) == CGAL::COPLANAR;
      }))
    return false;
  // Two convex sets meet exactly when an edge of one meets the other (docs/area-sources.md).
  for (std::size_t k = 0; k < source.size(); ++k)
    if (segment_meets(solid, source[k], source[(k + 1) % source.size()])) return true;
  for (const Face& face : solid.faces())
    for (std::size_t k = 0; k < face.vertices.size(); ++k) {
      const Segment3 edge(face.vertices[k], face.vertices[(k + 1) % face.vertices.size()]);
      for (std::size_t i = 1; i + 1 < source.size(); ++i)
        if (CGAL::do_intersect(edge, Triangle3(source[0], source[i], source[i + 1]))) return true;
    }
  return false;
}

std::vector<Plane3> separating_planes(const ConvexPolyhedron& solid,
                                      const std::vector<Point3>& source) {
  const std::vector<Point3>& v = solid.vertices();
  std::vector<Plane3> planes;
  const std::size_t n = source.size();
  // An edge of the source and a vertex of the solid.
  for (std::size_t k = 0; k < n; ++k)
    for (const Point3& w : v)
      add_if_separating(source[k], source[(k + 1) % n], w, v, source, planes);
  // A vertex of the source and an edge of the solid (each edge once: from its smaller id).
  for (const Face& face : solid.faces())
    for (std::size_t k = 0; k < face.vertices.size(); ++k) {
      const std::size_t next = (k + 1) % face.vertices.size();
      if (face.vertex_ids[k] > face.vertex_ids[next]) continue;
      for (const Point3& q : source)
        add_if_separating(face.vertices[k], face.vertices[next], q, v, source, planes);
    }
  // A face of the solid, and the source's own plane.
  for (const Face& face : solid.faces())
    add_if_separating(face.vertices[0], face.vertices[1], face.vertices[2], v, source, planes);
  add_if_separating(source[0], source[1], source[2], v, source, planes);
  return planes;
}

std::optional<AreaVolumes> area_volumes(const ConvexPolyhedron& solid,
                                        const std::vector<Point3>& source) {
  // An occluder with no face turned toward any vertex casts nothing, even when the source
  // lies on it (a panel on a ceiling's lower face).
  const bool casts = std::any_of(solid.faces().begin(), solid.faces().end(), [&](const Face& f) {
    return std::any_of(source.begin(), source.end(),
                       [&](const Point3& q) { return turned_toward(f, q); });
  });
  if (!casts) return std::nullopt;
  if (polygon_meets_solid(source, solid))
    throw std::domain_error("the area source touches or passes through an occluder");
  AreaVolumes volumes;
  volumes.penumbra.planes = separating_planes(solid, source);
  if (volumes.penumbra.planes.empty()) return std::nullopt;
  OpenVolume umbra;
  for (const Point3& q : source) {
    const OpenVolume shadow = point_shadow_volume(solid, q);
    if (shadow.planes.empty()) return volumes;
    for (const Plane3& plane : shadow.planes)
      if (std::find(umbra.planes.begin(), umbra.planes.end(), plane) == umbra.planes.end())
        umbra.planes.push_back(plane);
  }
  volumes.umbra = std::move(umbra);
  return volumes;
}

}  // namespace penumbra
