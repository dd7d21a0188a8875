#include "penumbra/shadow/face_shadow.h"

#include <iterator>

#include <CGAL/Polygon_set_2.h>

namespace penumbra {
namespace {

using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

Ring2 to_ring(const Polygon& polygon) {
  return canonical_ring(Ring2(polygon.vertices_begin(), polygon.vertices_end()));
}

// converts a regularized polygon set to the canonical region form.
Region2 to_region(const PolygonSet& set) {
  std::vector<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<Polygon2> polygons;
  for (const PolygonWithHoles& part : parts) {
    Polygon2 polygon{to_ring(part.outer_boundary()), {}};
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole)
      polygon.holes.push_back(to_ring(*hole));
    polygons.push_back(std::move(polygon));
  }
  return canonical_region(std::move(polygons));
}

}  // namespace

Ring2 face_ring(const Face& face) {
  Ring2 ring;
  for (const Point3& p : face.vertices) ring.push_back(face.frame.to_frame(p));
  return ring;
}

FaceShadow unlit_face(const Face& face) {
  FaceShadow result;
  result.faces_away = true;
  result.shadow = convex_region(face_ring(face));
  return result;
}

FaceShadow unite_shadows(const Face& face, std::vector<OccluderShadow> occluders) {
  FaceShadow result;
  const Ring2 ring = face_ring(face);
  if (occluders.empty()) {
    result.lit = convex_region(ring);
    return result;
  }
  std::vector<Polygon> polygons;
  for (const OccluderShadow& occluder : occluders)
    polygons.emplace_back(occluder.polygon.begin(), occluder.polygon.end());
  PolygonSet shadow;
  if (polygons.size() == 1)
    shadow.insert(polygons.front());
  else
    shadow.join(polygons.begin(), polygons.end());
  PolygonSet lit(Polygon(ring.begin(), ring.end()));
  lit.difference(shadow);
  result.shadow =
      polygons.size() == 1 ? convex_region(occluders.front().polygon) : to_region(shadow);
  result.lit = to_region(lit);
  result.occluders = std::move(occluders);
  return result;
}

}  // namespace penumbra
