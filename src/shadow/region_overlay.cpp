#include "penumbra/shadow/region_overlay.h"

#include <CGAL/box_intersection_d.h>

#include <map>
#include <memory>
#include <numeric>
#include <set>

#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_overlay_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_set_2.h>
#include <tbb/parallel_invoke.h>

#include "penumbra/base/parallel.h"

namespace penumbra {
namespace {

// Polygon sets whose arrangement faces also carry a count (besides the Boolean operations'
// own "contained" flag): a region is inserted as a polygon set and overlaid as an arrangement.
using Traits = CGAL::Gps_segment_traits_2<Kernel, std::vector<Point2>>;
using Dcel =
    CGAL::Arr_face_extended_dcel<Traits, std::size_t, CGAL::Arr_vertex_base<Traits::Point_2>,
                                 CGAL::Gps_halfedge_base<Traits::X_monotone_curve_2>,
                                 CGAL::Gps_face_base>;
using CountedSet = CGAL::Polygon_set_2<Kernel, std::vector<Point2>, Dcel>;
using Arrangement = CountedSet::Arrangement_2;

struct Sum {
  std::size_t operator()(std::size_t a, std::size_t b) const { return a + b; }
};
using SumOverlay = CGAL::Arr_face_overlay_traits<Arrangement, Arrangement, Arrangement, Sum>;

// One polygon of one of the regions, as the clusters gather them.
struct Piece {
  std::size_t region;
  const Polygon2* polygon;
};

// returns the pieces in clusters: two pieces whose bounding boxes (rounded outward) meet are
// in one cluster, so pieces of different clusters lie strictly apart and are overlaid
// apart.
std::vector<std::vector<Piece>> clusters_of(const std::vector<Piece>& pieces) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                          CGAL::Box_intersection_d::ID_EXPLICIT>;
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    CGAL::Bbox_2 box;
    for (const Point2& p : pieces[k].polygon->outer) box += p.bbox();
    boxes.emplace_back(box, k);
  }
  std::vector<std::size_t> parent(pieces.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    parent[root(a.handle())] = root(b.handle());
  });
  std::map<std::size_t, std::vector<Piece>> by_root;
  for (std::size_t k = 0; k < pieces.size(); ++k) by_root[root(k)].push_back(pieces[k]);
  std::vector<std::vector<Piece>> clusters;
  for (auto& entry : by_root) clusters.push_back(std::move(entry.second));
  return clusters;
}

// returns the arrangement of disjoint polygons whose faces count weight inside them and 0
// outside. The edges go in by a sweep that finds every meeting (CGAL::insert), not as
// polygons: canonical rings may touch themselves or each other with a vertex on an edge
// (canonical_ring drops the vertex that split that edge), which insertion as non-crossing
// curves does not allow. Inside is then told by parity, from the unbounded face outward:
// every edge is on the boundary of exactly one polygon.
std::unique_ptr<CountedSet> leaf(const std::vector<const Polygon2*>& polygons, std::size_t weight) {
  std::vector<Traits::Curve_2> segments;
  const auto add = [&](const Ring2& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k)
      segments.emplace_back(ring[k], ring[(k + 1) % ring.size()]);
  };
  for (const Polygon2* polygon : polygons) {
    add(polygon->outer);
    for (const Ring2& hole : polygon->holes) add(hole);
  }
  auto set = std::make_unique<CountedSet>();
  Arrangement& arrangement = set->arrangement();
  CGAL::insert(arrangement, segments.begin(), segments.end());
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) f->set_visited(false);
  std::vector<Arrangement::Face_handle> queue{arrangement.unbounded_face()};
  queue.front()->set_data(0);
  queue.front()->set_visited(true);
  while (!queue.empty()) {
    const Arrangement::Face_handle face = queue.back();
    queue.pop_back();
    const auto cross = [&](Arrangement::Ccb_halfedge_circulator ccb) {
      auto halfedge = ccb;
      do {
        const Arrangement::Face_handle other = halfedge->twin()->face();
        if (!other->visited()) {
          other->set_data(face->data() == 0 ? weight : 0);
          other->set_visited(true);
          queue.push_back(other);
        }
      } while (++halfedge != ccb);
    };
    if (!face->is_unbounded()) cross(face->outer_ccb());
    for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole) cross(*hole);
  }
  return set;
}

// returns the overlay of leaves[begin, end), each face counting the sum of the faces it lies
// in: halves overlaid recursively, so each edge takes part in log2(n) overlays.
std::unique_ptr<CountedSet> overlay(std::vector<std::unique_ptr<CountedSet>>& leaves,
                                    std::size_t begin, std::size_t end) {
  if (end - begin == 1) return std::move(leaves[begin]);
  const std::size_t middle = begin + (end - begin) / 2;
  std::unique_ptr<CountedSet> low, high;
  tbb::parallel_invoke([&] { low = overlay(leaves, begin, middle); },
                       [&] { high = overlay(leaves, middle, end); });
  auto both = std::make_unique<CountedSet>();
  SumOverlay sum;
  CGAL::overlay(low->arrangement(), high->arrangement(), both->arrangement(), sum);
  return both;
}

// returns the polygons of the arrangement's faces by key (faces of key < 0 left out), read in
// one pass: faces of one key that share an edge form one polygon (union-find); the boundary
// of each key's set (its halfedges with that key on the left and another on the right) is
// traced into rings, turning at each vertex into the next boundary halfedge of the same key
// around it, so that sets touching at a vertex give separate rings. Counter-clockwise rings
// are the polygons' outer boundaries, clockwise ones their holes, each in the polygon of the
// face on its left. Not polygons_with_holes: it builds rings from the curves' endpoints, and
// the overlay keeps the input curves' directions, not the ones it expects (a face of four
// vertices came out as a triangle with a repeated corner).
template <typename Key>
std::map<std::ptrdiff_t, std::vector<Polygon2>> polygons_by_key(const Arrangement& arrangement,
                                                                const Key& key_of) {
  using Face = Arrangement::Face_const_handle;
  using Halfedge = Arrangement::Halfedge_const_handle;
  std::map<Face, std::size_t> index;
  std::vector<std::ptrdiff_t> keys;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f)
    if (key_of(f->data()) >= 0) {
      index.emplace(f, keys.size());
      keys.push_back(key_of(f->data()));
    }
  const auto key = [&](Face f) { return key_of(f->data()); };
  std::vector<std::size_t> parent(keys.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    const Face a = e->face(), b = e->twin()->face();
    if (a != b && key(a) >= 0 && key(a) == key(b)) parent[root(index.at(a))] = root(index.at(b));
  }
  const auto boundary = [&](Halfedge h) {
    return key(h->face()) >= 0 && key(h->face()) != key(h->twin()->face());
  };
  std::map<std::size_t, Polygon2> polygons;  // by the root of their faces
  std::set<Halfedge> traced;
  for (auto h = arrangement.halfedges_begin(); h != arrangement.halfedges_end(); ++h) {
    if (!boundary(h) || traced.count(h)) continue;
    Ring2 ring;
    Halfedge at = h;
    do {
      traced.insert(at);
      ring.push_back(at->source()->point());
      Halfedge next = at->next();
      while (!boundary(next)) next = next->twin()->next();
      at = next;
    } while (at != Halfedge(h));
    Ring2 canonical = canonical_ring(ring);
    if (canonical.empty()) continue;
    Polygon2& polygon = polygons[root(index.at(h->face()))];
    if (CGAL::orientation_2(canonical.begin(), canonical.end(), Kernel()) == CGAL::COUNTERCLOCKWISE)
      polygon.outer = std::move(canonical);
    else
      polygon.holes.push_back(std::move(canonical));
  }
  std::map<std::ptrdiff_t, std::vector<Polygon2>> by_key;
  for (auto& [component, polygon] : polygons)
    if (!polygon.outer.empty()) by_key[keys[component]].push_back(std::move(polygon));
  return by_key;
}

// What one cluster contributes: its polygons by count (1 and more), and its extent (where
// the count is at least 1).
struct ClusterParts {
  std::map<std::size_t, std::vector<Polygon2>> by_count;
  std::vector<Polygon2> extent;
};

ClusterParts overlay_cluster(const std::vector<Piece>& cluster) {
  ClusterParts parts;
  if (cluster.size() == 1) {  // one polygon: itself, count 1
    parts.by_count[1] = {*cluster.front().polygon};
    parts.extent = {*cluster.front().polygon};
    return parts;
  }
  std::map<std::size_t, std::vector<const Polygon2*>> by_region;
  for (const Piece& piece : cluster) by_region[piece.region].push_back(piece.polygon);
  std::vector<std::unique_ptr<CountedSet>> leaves;
  for (const auto& entry : by_region) leaves.push_back(leaf(entry.second, 1));
  const std::unique_ptr<CountedSet> all = overlay(leaves, 0, leaves.size());
  for (auto& [count, polygons] : polygons_by_key(all->arrangement(), [](std::size_t data) {
         return data > 0 ? static_cast<std::ptrdiff_t>(data) : -1;
       }))
    parts.by_count[static_cast<std::size_t>(count)] = std::move(polygons);
  parts.extent = std::move(
      polygons_by_key(all->arrangement(), [](std::size_t data) { return data > 0 ? 0 : -1; })[0]);
  return parts;
}

// returns window less the polygons of extents (disjoint): the faces of the window's and the
// extents' overlay that lie in the window only.
Region2 window_less(const Polygon2& window, const std::vector<Polygon2>& extents) {
  std::vector<std::unique_ptr<CountedSet>> leaves;
  leaves.push_back(leaf({&window}, 2));
  std::vector<const Polygon2*> covered;
  for (const Polygon2& polygon : extents) covered.push_back(&polygon);
  if (!covered.empty()) leaves.push_back(leaf(covered, 1));
  const std::unique_ptr<CountedSet> all = overlay(leaves, 0, leaves.size());
  return canonical_region(std::move(
      polygons_by_key(all->arrangement(), [](std::size_t data) { return data == 2 ? 0 : -1; })[0]));
}

}  // namespace

std::vector<Coverage> coverage(const Polygon2& window, const std::vector<const Region2*>& regions,
                               std::size_t base) {
  std::vector<Piece> pieces;
  for (std::size_t r = 0; r < regions.size(); ++r)
    for (const Polygon2& polygon : regions[r]->polygons) pieces.push_back({r, &polygon});
  const std::vector<std::vector<Piece>> clusters = clusters_of(pieces);
  std::vector<ClusterParts> cluster_parts(clusters.size());
  for_each_index(clusters.size(), clusters.size() > 1,
                 [&](std::size_t c) { cluster_parts[c] = overlay_cluster(clusters[c]); });

  // Clusters lie strictly apart, and count 0 lies outside every extent: each count's
  // polygons are its clusters' together.
  std::map<std::size_t, std::vector<Polygon2>> by_count;
  std::vector<Polygon2> extents;
  for (ClusterParts& parts : cluster_parts) {
    for (auto& [count, polygons] : parts.by_count)
      std::move(polygons.begin(), polygons.end(), std::back_inserter(by_count[count]));
    std::move(parts.extent.begin(), parts.extent.end(), std::back_inserter(extents));
  }
  std::vector<Coverage> result;
  if (Region2 rest = window_less(window, extents); !rest.empty())
    result.push_back({base, std::move(rest)});
  for (auto& [count, polygons] : by_count)
    if (Region2 region = canonical_region(std::move(polygons)); !region.empty())
      result.push_back({count + base, std::move(region)});
  return result;
}

}  // namespace penumbra
