#include "region_set.h"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <iterator>
#include <numeric>
#include <optional>

#include <CGAL/Polygon_set_2.h>

#include "convex_difference.h"
#include "disjoint_sets.h"
#include "exact_compare.h"
#include "half_plane.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "polygon_set_region.h"
#include "segment_arrangement.h"

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

// returns the pairs of rings whose boxes (rounded outward) meet.
std::vector<std::pair<std::size_t, std::size_t>> box_pairs(const std::vector<Ring2>& rings) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                          CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    CGAL::Bbox_2 box;
    for (const Point2& p : rings[k]) box += p.bbox();
    boxes.emplace_back(box, k);
  }
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    candidates.emplace_back(a.handle(), b.handle());
  });
  return candidates;
}

}  // namespace

Region2 unite_minus(const std::vector<Ring2>& rings, const std::vector<Ring2>& subtract) {
  PolygonSet set = join(rings);
  if (!subtract.empty()) set.difference(join(subtract));
  return region_of(set);
}

ShadowSets shadow_sets(const std::vector<Ring2>& shadows, const std::vector<Ring2>& umbrae,
                       const Ring2& window) {
  const Ring2 whole = canonical_ring(window);
  const auto covers = [&](const std::vector<Ring2>& rings) {
    return std::any_of(rings.begin(), rings.end(),
                       [&](const Ring2& ring) { return same_ring(ring, whole); });
  };
  ShadowSets sets;
  if (covers(shadows)) {
    sets.shadow = convex_region(window);
    if (covers(umbrae)) {
      sets.umbra = sets.shadow;
      return sets;
    }
    PolygonSet penumbra = join({window});
    const PolygonSet umbra = join(umbrae);
    penumbra.difference(umbra);
    sets.umbra = region_of(umbra);
    sets.penumbra = region_of(penumbra);
    return sets;
  }
  const PolygonSet shadow = join(shadows), umbra = join(umbrae);
  PolygonSet penumbra = shadow, lit = join({window});
  if (!umbrae.empty()) penumbra.difference(umbra);
  if (!shadows.empty()) lit.difference(shadow);
  return {region_of(shadow), region_of(umbra), region_of(penumbra), region_of(lit)};
}

Region2 unite_regions(const std::vector<Region2>& regions) {
  std::vector<PolygonWithHoles> parts;
  for (const Region2& region : regions) {
    std::vector<PolygonWithHoles> more = polygons_with_holes<PolygonWithHoles>(region);
    std::move(more.begin(), more.end(), std::back_inserter(parts));
  }
  if (parts.empty()) return {};
  PolygonSet set;
  if (parts.size() == 1)
    set.insert(parts.front());
  else
    set.join(parts.begin(), parts.end());
  return region_of(set);
}

std::vector<std::vector<std::size_t>> touching_groups(const std::vector<Ring2>& rings) {
  // Union-find over the pairs whose boxes (rounded outward) meet and whose closures meet.
  DisjointSets sets(rings.size());
  const auto candidates = box_pairs(rings);
  std::vector<char> touching(candidates.size());
  for_each_index(candidates.size(), true, [&](std::size_t k) {
    touching[k] = !strictly_apart(rings[candidates[k].first], rings[candidates[k].second]);
  });
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (touching[k]) sets.join(candidates[k].first, candidates[k].second);
  std::vector<std::vector<std::size_t>> groups;
  std::vector<long> group_of(rings.size(), -1);
  for (std::size_t k = 0; k < rings.size(); ++k) {
    long& group = group_of[sets.root(k)];
    if (group < 0) {
      group = static_cast<long>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(group)].push_back(k);
  }
  return groups;
}

namespace {

// A lit face being assembled: its outer boundary (counter-clockwise) and its holes.
struct LitFace {
  Polygon outer;
  std::vector<Polygon> holes;
  Exact area;  // of outer, to find the innermost face holding a point
};

// returns true when point is strictly inside polygon (it is never on its boundary here).
bool inside(const Polygon& polygon, const Point2& point) {
  return CGAL::bounded_side_2(polygon.vertices_begin(), polygon.vertices_end(), point) ==
         CGAL::ON_BOUNDED_SIDE;
}

// returns true when some vertex of polygon lies on the boundary of the convex window.
bool touches(const Polygon& polygon, const Ring2& window) {
  for (std::size_t k = 0; k < window.size(); ++k)
    for (auto v = polygon.vertices_begin(); v != polygon.vertices_end(); ++v)
      if (orientation_sign(window[k], window[(k + 1) % window.size()], *v) == CGAL::ZERO)
        return true;
  return false;
}

}  // namespace

namespace {

// returns each group's union on its own (across threads): groups are strictly apart, so
// their pieces are the faces the union of all rings has.
std::vector<std::vector<PolygonWithHoles>> group_pieces(
    const std::vector<Ring2>& rings, const std::vector<std::vector<std::size_t>>& groups) {
  std::vector<std::vector<PolygonWithHoles>> pieces(groups.size());
  for_each_index(groups.size(), true, [&](std::size_t g) {
    if (groups[g].size() == 1) {
      const Ring2& ring = rings[groups[g].front()];
      pieces[g].emplace_back(Polygon(ring.begin(), ring.end()));
      return;
    }
    std::vector<Ring2> members;
    for (std::size_t k : groups[g]) members.push_back(rings[k]);
    join(members).polygons_with_holes(std::back_inserter(pieces[g]));
  });
  return pieces;
}

// returns parts as a canonical region (with area when given).
Region2 canonical(const std::vector<PolygonWithHoles>& parts, std::optional<Exact> area = {}) {
  std::vector<Polygon2> polygons(parts.size());
  for_each_index(parts.size(), true, [&](std::size_t k) {
    polygons[k].outer = to_ring(parts[k].outer_boundary());
    for (auto hole = parts[k].holes_begin(); hole != parts[k].holes_end(); ++hole)
      polygons[k].holes.push_back(to_ring(*hole));
  });
  return canonical_region(std::move(polygons), std::move(area));
}

// returns the union of the rings from their groups' pieces.
Region2 union_of(const std::vector<Ring2>& rings,
                 const std::vector<std::vector<PolygonWithHoles>>& pieces) {
  if (rings.size() == 1) return convex_region(rings.front());
  std::vector<PolygonWithHoles> all;
  for (const std::vector<PolygonWithHoles>& group : pieces)
    all.insert(all.end(), group.begin(), group.end());
  return canonical(all);
}

}  // namespace

Region2 unite_groups(const std::vector<Ring2>& rings,
                     const std::vector<std::vector<std::size_t>>& groups) {
  if (rings.size() == 1) return convex_region(rings.front());
  // Each group's union is where the pairwise arrangement of its rings' edges counts one
  // ring or more (segment_arrangement.h: the rings are counter-clockwise, so each adds one
  // on its left); the same faces a polygon set's union has.
  std::vector<std::vector<Polygon2>> pieces(groups.size());
  std::vector<Enclosure> areas(groups.size());
  for_each_index(groups.size(), true, [&](std::size_t g) {
    if (groups[g].size() == 1) {
      if (Ring2 ring = canonical_ring(rings[groups[g].front()]); !ring.empty()) {
        pieces[g].push_back({std::move(ring), {}});
        areas[g] = area_enclosure(pieces[g].back());
      }
      return;
    }
    std::vector<LayerSegment> segments;
    for (const std::size_t k : groups[g]) {
      const Ring2 ring = canonical_ring(rings[k]);
      for (std::size_t i = 0; i < ring.size(); ++i)
        segments.push_back({ring[i], ring[(i + 1) % ring.size()], 1});
    }
    if (segments.empty()) return;
    for (KeyPolygons& united : polygons_by_count(
             arrange(segments), [](long count) { return count > 0 ? 0L : -1L; },
             TraceSide::outside)) {
      pieces[g] = std::move(united.polygons);
      areas[g] = std::move(united.area);
    }
  });
  std::vector<Polygon2> all;
  Enclosure area;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::move(pieces[g].begin(), pieces[g].end(), std::back_inserter(all));
    area.add(areas[g]);
  }
  return canonical_region(std::move(all), area);
}

std::pair<Region2, Region2> unite_and_complement(
    const std::vector<Ring2>& rings, const std::vector<std::vector<std::size_t>>& groups,
    const Ring2& window) {
  const std::vector<std::vector<PolygonWithHoles>> pieces = group_pieces(rings, groups);

  // The lit part: the window less the groups with a piece that touches its boundary (a
  // Boolean difference), whose faces and the other pieces' holes are the faces the other
  // pieces may lie in; each other piece is a hole of the innermost face holding one of its
  // vertices. What is subtracted is the union of those groups' rings, not their pieces made
  // into polygons again: a piece's outer boundary may touch itself at a vertex (a union
  // pinched by a thin inlet, as on faces of the FZK house at 14:00), which CGAL gives as one
  // polygon but cannot insert again as one (its sweep crashed on it).
  std::vector<LitFace> faces;
  std::vector<const PolygonWithHoles*> inner;
  {
    PolygonSet rest;
    rest.insert(Polygon(window.begin(), window.end()));
    std::vector<Ring2> touching;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (std::any_of(pieces[g].begin(), pieces[g].end(), [&](const PolygonWithHoles& piece) {
            return touches(piece.outer_boundary(), window);
          }))
        for (std::size_t k : groups[g]) touching.push_back(rings[k]);
      else
        for (const PolygonWithHoles& piece : pieces[g]) inner.push_back(&piece);
    }
    if (!touching.empty()) rest.difference(join(touching));
    std::vector<PolygonWithHoles> parts;
    rest.polygons_with_holes(std::back_inserter(parts));
    for (PolygonWithHoles& part : parts)
      faces.push_back({part.outer_boundary(),
                       std::vector<Polygon>(part.holes_begin(), part.holes_end()), Exact()});
    for (const PolygonWithHoles* piece : inner)
      for (auto hole = piece->holes_begin(); hole != piece->holes_end(); ++hole) {
        Polygon outer = *hole;
        outer.reverse_orientation();
        faces.push_back({std::move(outer), {}, Exact()});
      }
  }
  for_each_index(faces.size(), true, [&](std::size_t f) {
    faces[f].area =
        signed_area(Ring2(faces[f].outer.vertices_begin(), faces[f].outer.vertices_end()));
  });
  // Point location by boxes, then exactly; nested candidates: the smallest holds it.
  std::vector<CGAL::Bbox_2> face_boxes;
  for (const LitFace& face : faces) face_boxes.push_back(face.outer.bbox());
  std::vector<long> home(inner.size(), -1);
  for_each_index(inner.size(), true, [&](std::size_t p) {
    const Point2& probe = *inner[p]->outer_boundary().vertices_begin();
    const CGAL::Bbox_2 at = probe.bbox();
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (CGAL::do_overlap(face_boxes[f], at) && inside(faces[f].outer, probe) &&
          (home[p] < 0 || faces[f].area < faces[static_cast<std::size_t>(home[p])].area))
        home[p] = static_cast<long>(f);
  });
  if (std::find(home.begin(), home.end(), -1) != home.end()) {
    // No face holds a piece (cannot happen for pieces strictly inside the window): the
    // Boolean difference of everything decides instead.
    PolygonSet rest = join({window});
    rest.difference(join(rings));
    return {rings.size() == 1 ? convex_region(rings.front()) : region_of(join(rings)),
            region_of(rest)};
  }
  for (std::size_t p = 0; p < inner.size(); ++p) {
    Polygon hole = inner[p]->outer_boundary();
    hole.reverse_orientation();
    faces[static_cast<std::size_t>(home[p])].holes.push_back(std::move(hole));
  }

  std::vector<PolygonWithHoles> lit;
  for (LitFace& face : faces) lit.emplace_back(face.outer, face.holes.begin(), face.holes.end());
  Region2 shadow = union_of(rings, pieces);
  // The lit part and the shadow tile the window: its area is the window's less theirs.
  const Exact lit_area = exact_number(exact_value(signed_area(window)) - exact_value(shadow.area));
  return {std::move(shadow), canonical(lit, lit_area)};
}

bool interiors_overlap(const Ring2& a, const Ring2& b) {
  return ring_with_area(clip_to_convex(a, b)).has_value();
}

bool any_interiors_overlap(const std::vector<Ring2>& rings) {
  const auto candidates = box_pairs(rings);
  return std::any_of(candidates.begin(), candidates.end(), [&](const auto& pair) {
    return interiors_overlap(rings[pair.first], rings[pair.second]);
  });
}

}  // namespace penumbra::detail
