#include "penumbra/shadow/region_overlay.h"

#include <CGAL/box_intersection_d.h>

#include <iterator>
#include <map>
#include <numeric>

#include "disjoint_sets.h"
#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "segment_arrangement.h"

namespace penumbra {
namespace {

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
  detail::DisjointSets sets(pieces.size());
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    sets.join(a.handle(), b.handle());
  });
  std::map<std::size_t, std::vector<Piece>> by_root;
  for (std::size_t k = 0; k < pieces.size(); ++k) by_root[sets.root(k)].push_back(pieces[k]);
  std::vector<std::vector<Piece>> clusters;
  for (auto& entry : by_root) clusters.push_back(std::move(entry.second));
  return clusters;
}

// A region to overlay: its polygons (canonical rings, inside on the left of each) and what
// it adds to the count of the points it holds.
struct Layer {
  std::vector<const Polygon2*> polygons;
  long weight = 1;
};

// returns the overlay of layers: the pairwise arrangement of their rings' segments
// (segment_arrangement.h), each face counting the weights of the layers that hold it.
detail::SegmentArrangement overlay(const std::vector<Layer>& layers) {
  std::vector<detail::LayerSegment> segments;
  for (const Layer& layer : layers) {
    const auto add = [&](const Ring2& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i)
        segments.push_back({ring[i], ring[(i + 1) % ring.size()], layer.weight});
    };
    for (const Polygon2* polygon : layer.polygons) {
      add(polygon->outer);
      for (const Ring2& hole : polygon->holes) add(hole);
    }
  }
  return detail::arrange(segments);
}

// Polygons, and an enclosure of their total area.
struct Parts {
  std::vector<Polygon2> polygons;
  Enclosure area;

  void add(Parts&& other) {
    std::move(other.polygons.begin(), other.polygons.end(), std::back_inserter(polygons));
    area.add(other.area);
  }
};

template <typename Key>
std::map<std::ptrdiff_t, Parts> polygons_by_key(const detail::SegmentArrangement& overlay,
                                                const Key& key_of) {
  std::map<std::ptrdiff_t, Parts> by_key;
  for (detail::KeyPolygons& entry : detail::polygons_by_count(
           overlay, [&](long count) { return static_cast<long>(key_of(count)); }))
    by_key[entry.key] = {std::move(entry.polygons), std::move(entry.area)};
  return by_key;
}

// What one cluster contributes: its polygons by count (1 and more), and its extent (where
// the count is at least 1).
struct ClusterParts {
  std::map<std::size_t, Parts> by_count;
  std::vector<Polygon2> extent;
};

ClusterParts overlay_cluster(const std::vector<Piece>& cluster) {
  ClusterParts parts;
  if (cluster.size() == 1) {  // one polygon: itself, count 1
    const Polygon2& polygon = *cluster.front().polygon;
    parts.by_count[1] = {{polygon}, area_enclosure(polygon)};
    parts.extent = {polygon};
    return parts;
  }
  std::map<std::size_t, Layer> by_region;
  for (const Piece& piece : cluster) by_region[piece.region].polygons.push_back(piece.polygon);
  std::vector<Layer> layers;
  for (auto& entry : by_region) layers.push_back(std::move(entry.second));
  const detail::SegmentArrangement all = overlay(layers);
  for (auto& [count, polygons] : polygons_by_key(
           all, [](long data) { return data > 0 ? static_cast<std::ptrdiff_t>(data) : -1; }))
    parts.by_count[static_cast<std::size_t>(count)] = std::move(polygons);
  parts.extent =
      std::move(polygons_by_key(all, [](long data) { return data > 0 ? 0 : -1; })[0].polygons);
  return parts;
}

// returns the polygons of the faces of the overlay of layers whose count is count.
Region2 region_counting(const std::vector<Layer>& layers, long count) {
  const detail::SegmentArrangement all = overlay(layers);
  Parts parts =
      std::move(polygons_by_key(all, [count](long data) { return data == count ? 0 : -1; })[0]);
  return canonical_region(std::move(parts.polygons), parts.area);
}

// returns window less the polygons of extents (disjoint): the faces of the window's and the
// extents' overlay that lie in the window only.
Region2 window_less(const Polygon2& window, const std::vector<Polygon2>& extents) {
  std::vector<Layer> layers{{{&window}, 2}, {{}, 1}};
  for (const Polygon2& polygon : extents) layers.back().polygons.push_back(&polygon);
  return region_counting(layers, 2);
}

}  // namespace

Region2 intersection(const Region2& a, const Region2& b) {
  std::vector<Layer> layers{{{}, 1}, {{}, 2}};
  for (const Polygon2& polygon : a.polygons) layers[0].polygons.push_back(&polygon);
  for (const Polygon2& polygon : b.polygons) layers[1].polygons.push_back(&polygon);
  return region_counting(layers, 3);
}

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
  std::map<std::size_t, Parts> by_count;
  std::vector<Polygon2> extents;
  for (ClusterParts& parts : cluster_parts) {
    for (auto& [count, polygons] : parts.by_count) by_count[count].add(std::move(polygons));
    std::move(parts.extent.begin(), parts.extent.end(), std::back_inserter(extents));
  }
  std::vector<Coverage> result;
  if (Region2 rest = window_less(window, extents); !rest.empty())
    result.push_back({base, std::move(rest)});
  for (auto& [count, parts] : by_count)
    if (Region2 region = canonical_region(std::move(parts.polygons), parts.area); !region.empty())
      result.push_back({count + base, std::move(region)});
  return result;
}

}  // namespace penumbra
