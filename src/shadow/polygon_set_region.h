#pragma once
// Conversions between CGAL's polygon sets and penumbra's canonical regions (private to
// shadow/).

#include <iterator>
#include <vector>

#include <CGAL/Polygon_with_holes_2.h>

#include "penumbra/shadow/region.h"

namespace penumbra::detail {

// returns a CGAL polygon's ring in canonical form.
template <typename Polygon>
Ring2 to_ring(const Polygon& polygon) {
  return canonical_ring(Ring2(polygon.vertices_begin(), polygon.vertices_end()));
}

// returns the canonical region of a polygon set.
template <typename PolygonSet>
Region2 region_of(const PolygonSet& set) {
  std::vector<typename PolygonSet::Polygon_with_holes_2> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<Polygon2> polygons;
  for (const auto& part : parts) {
    Polygon2 polygon{to_ring(part.outer_boundary()), {}};
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole)
      polygon.holes.push_back(to_ring(*hole));
    polygons.push_back(std::move(polygon));
  }
  return canonical_region(std::move(polygons));
}

// returns the polygons of a region as CGAL polygons with holes (of the set type's kind).
template <typename PolygonWithHoles>
std::vector<PolygonWithHoles> polygons_with_holes(const Region2& region) {
  using Polygon = typename PolygonWithHoles::Polygon_2;
  std::vector<PolygonWithHoles> parts;
  for (const Polygon2& polygon : region.polygons) {
    PolygonWithHoles part(Polygon(polygon.outer.begin(), polygon.outer.end()));
    for (const Ring2& hole : polygon.holes) part.add_hole(Polygon(hole.begin(), hole.end()));
    parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace penumbra::detail
