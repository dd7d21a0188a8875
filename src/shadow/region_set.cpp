#include "region_set.h"

#include <iterator>

#include <CGAL/Polygon_set_2.h>

#include "half_plane.h"

namespace penumbra::detail {
namespace {

using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

PolygonSet join(const std::vector<Ring2>& rings) {
  std::vector<Polygon> polygons;
  for (const Ring2& ring : rings) polygons.emplace_back(ring.begin(), ring.end());
  PolygonSet set;
  if (polygons.size() == 1) set.insert(polygons.front());
  if (polygons.size() > 1) set.join(polygons.begin(), polygons.end());
  return set;
}

Ring2 to_ring(const Polygon& polygon) {
  return canonical_ring(Ring2(polygon.vertices_begin(), polygon.vertices_end()));
}

Region2 region_of(const PolygonSet& set) {
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

Region2 unite_minus(const std::vector<Ring2>& rings, const std::vector<Ring2>& subtract) {
  PolygonSet set = join(rings);
  if (!subtract.empty()) set.difference(join(subtract));
  return region_of(set);
}

std::pair<Region2, Region2> unite_and_complement(const std::vector<Ring2>& rings,
                                                 const Ring2& window) {
  const PolygonSet shadow = join(rings);
  PolygonSet rest = join({window});
  rest.difference(shadow);
  return {rings.size() == 1 ? convex_region(rings.front()) : region_of(shadow), region_of(rest)};
}

bool interiors_overlap(const Ring2& a, const Ring2& b) {
  return ring_with_area(clip_to_convex(a, b)).has_value();
}

}  // namespace penumbra::detail
