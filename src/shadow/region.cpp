#include "penumbra/shadow/region.h"

#include <algorithm>
#include <limits>
#include <memory>

#include <tbb/parallel_sort.h>

#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/exact_sum.h"
#include "penumbra/geometry/interval.h"

namespace penumbra {
namespace {

bool point_less(const Point2& a, const Point2& b) {
  return CGAL::compare_xy(a, b) == CGAL::SMALLER;
}

bool ring_less(const Ring2& a, const Ring2& b) {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), point_less);
}

// returns twice the signed area of the ring of corners first to last in rationals (the
// shoelace formula).
Rational twice_signed_area(const Point2* first, const Point2* last) {
  Rational twice = 0;
  for (const Point2* at = first; at != last; ++at) {
    const RationalPoint2& p = exact_value(*at);
    const RationalPoint2& q = exact_value(at + 1 != last ? at[1] : *first);
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return twice;
}

Rational twice_signed_area(const Ring2& ring) {
  return twice_signed_area(ring.data(), ring.data() + ring.size());
}

// The edges of a polygon's rings in runs of at most this many, summed across threads: the
// ground of a city is a few polygons with up to 10^5 corners.
constexpr std::size_t kEdgesPerRun = 4096;

}  // namespace

Enclosure area_enclosure(const Polygon2& polygon) {
  struct Run {
    const Ring2* ring;
    std::size_t from, to;  // edges from corner from to corner to (mod its size)
    ShoelaceEnclosure twice;
  };
  std::vector<Run> runs;
  std::size_t edges = 0;
  const auto add = [&](const Ring2& ring) {
    edges += ring.size();
    for (std::size_t from = 0; from < ring.size(); from += kEdgesPerRun)
      runs.push_back({&ring, from, std::min(ring.size(), from + kEdgesPerRun), {}});
  };
  add(polygon.outer);
  for (const Ring2& hole : polygon.holes) add(hole);
  for_each_index(
      runs.size(), edges > kEdgesPerRun,
      [&](std::size_t k) {
        Run& run = runs[k];
        run.twice.add_path(run.to - run.from + 1, [&](std::size_t i) -> const RationalPoint2& {
          return exact_value((*run.ring)[(run.from + i) % run.ring->size()]);
        });
      },
      4);
  ShoelaceEnclosure twice;
  for (const Run& run : runs) twice.add(run.twice);
  return twice.area();
}

namespace {

// The rings of polygons in one array (what an area computed later keeps: one allocation,
// not one per ring).
class FlatPolygons {
 public:
  explicit FlatPolygons(const std::vector<Polygon2>& polygons) {
    std::size_t corners = 0, rings = 0;
    for (const Polygon2& polygon : polygons) {
      corners += polygon.outer.size();
      rings += 1 + polygon.holes.size();
      for (const Ring2& hole : polygon.holes) corners += hole.size();
    }
    points_.reserve(corners);
    ring_end_.reserve(rings);
    polygon_end_.reserve(polygons.size());
    const auto add = [&](const Ring2& ring) {
      points_.insert(points_.end(), ring.begin(), ring.end());
      ring_end_.push_back(points_.size());
    };
    for (const Polygon2& polygon : polygons) {
      add(polygon.outer);
      for (const Ring2& hole : polygon.holes) add(hole);
      polygon_end_.push_back(ring_end_.size());
    }
  }

  // returns the exact area of the polygons: each polygon's, added pairwise.
  Rational area() const {
    std::vector<Rational> areas;
    std::size_t ring = 0;
    for (const std::size_t end : polygon_end_) {
      Rational twice = 0;
      for (; ring < end; ++ring) {
        const Point2* first = points_.data() + (ring == 0 ? 0 : ring_end_[ring - 1]);
        twice += twice_signed_area(first, points_.data() + ring_end_[ring]);
      }
      areas.push_back(twice / 2);
    }
    return pairwise_sum(std::move(areas));
  }

 private:
  std::vector<Point2> points_;
  std::vector<std::size_t> ring_end_, polygon_end_;
};

}  // namespace

Exact signed_area(const Ring2& ring) {
  return exact_number(twice_signed_area(ring) / 2);
}

CGAL::Sign area_sign(const Ring2& ring) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    Interval twice = 0;
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const auto& p = CGAL::approx(ring[k]);
      const auto& q = CGAL::approx(ring[(k + 1) % n]);
      twice += p.x() * q.y() - q.x() * p.y();
    }
    const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(twice);
    if (CGAL::is_certain(sign)) return sign.make_certain();
  }
  return CGAL::sign(twice_signed_area(ring));
}

Ring2 canonical_ring(const Ring2& ring) {
  Ring2 out;
  for (const Point2& p : ring)
    if (out.empty() || !same_point(out.back(), p)) out.push_back(p);
  while (out.size() > 1 && same_point(out.front(), out.back())) out.pop_back();
  // Drop vertices whose neighbours are collinear with them, until none is left.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    for (std::size_t k = 0; k < out.size() && out.size() >= 3; ++k) {
      const std::size_t n = out.size();
      const Point2& before = out[(k + n - 1) % n];
      const Point2& after = out[(k + 1) % n];
      if (orientation_sign(before, out[k], after) == CGAL::ZERO) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
        --k;
      }
    }
  }
  if (out.size() < 3) return {};
  // Start at the smallest vertex; a ring that touches itself there passes it more than once,
  // and then starts at the pass whose following vertices are smallest, so that the form
  // does not depend on where the ring was traced from.
  const std::size_t n = out.size();
  std::size_t start =
      static_cast<std::size_t>(std::min_element(out.begin(), out.end(), point_less) - out.begin());
  for (std::size_t k = start + 1; k < n; ++k) {
    if (!same_point(out[k], out[start])) continue;
    for (std::size_t i = 1; i < n; ++i) {
      const CGAL::Comparison_result c = CGAL::compare_xy(out[(k + i) % n], out[(start + i) % n]);
      if (c == CGAL::EQUAL) continue;
      if (c == CGAL::SMALLER) start = k;
      break;
    }
  }
  std::rotate(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(start), out.end());
  return out;
}

namespace {

// sorts holes and polygons. The polygons are sorted by their first corners' x intervals
// (in one array, not behind each polygon's handles), and by their outer rings exactly where
// the intervals overlap: the order is ring_less's.
void sort_polygons(std::vector<Polygon2>& polygons) {
  for_each_index(
      polygons.size(), polygons.size() > 64,
      [&](std::size_t k) {
        std::sort(polygons[k].holes.begin(), polygons[k].holes.end(), ring_less);
      },
      16);
  if (polygons.size() < 2) return;
  struct Key {
    double low, high;  // the first corner's x lies in [low, high]
    std::size_t polygon;
  };
  std::vector<Key> keys(polygons.size());
  for_each_index(
      polygons.size(), polygons.size() > 4096,
      [&](std::size_t k) {
        const Ring2& outer = polygons[k].outer;
        if (outer.empty()) {  // never apart from another
          keys[k] = {-std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity(), k};
          return;
        }
        const auto& x = CGAL::approx(outer.front()).x();
        keys[k] = {x.inf(), x.sup(), k};
      },
      1024);
  tbb::parallel_sort(keys.begin(), keys.end(), [&](const Key& a, const Key& b) {
    if (a.high < b.low) return true;
    if (b.high < a.low) return false;
    return ring_less(polygons[a.polygon].outer, polygons[b.polygon].outer);
  });
  std::vector<Polygon2> sorted;
  sorted.reserve(polygons.size());
  for (const Key& key : keys) sorted.push_back(std::move(polygons[key.polygon]));
  polygons = std::move(sorted);
}

// returns the area of polygons, enclosed by areas: their exact sum is computed from the
// rings when first asked for.
Exact deferred_area(const std::vector<Polygon2>& polygons, const std::vector<Enclosure>& areas) {
  return exact_sum(
      areas, [flat = std::make_shared<const FlatPolygons>(polygons)] { return flat->area(); });
}

}  // namespace

Region2 canonical_region(std::vector<Polygon2> polygons, std::optional<Exact> area) {
  Region2 region;
  sort_polygons(polygons);
  if (area) {
    region.area = std::move(*area);
  } else if (!polygons.empty()) {
    // A ground under a city is one region of 10^4 polygons. Their exact areas, rationals of
    // unrelated denominators, are computed and added when the total's exact value is asked
    // for (exact_sum.h); until then integer enclosures of them (each polygon on its own
    // thread) give the interval and the printed double. The same for one polygon: most
    // areas are only printed, and the enclosure's integers cost less than the rational
    // shoelace's gcds (a shadow of every triangle of a mesh is such a region).
    std::vector<Enclosure> areas(polygons.size());
    for_each_index(
        polygons.size(), polygons.size() > 64,
        [&](std::size_t k) { areas[k] = area_enclosure(polygons[k]); }, 16);
    region.area = deferred_area(polygons, areas);
  }
  region.polygons = std::move(polygons);
  return region;
}

Region2 canonical_region(std::vector<Polygon2> polygons, const Enclosure& area) {
  Region2 region;
  sort_polygons(polygons);
  if (!polygons.empty()) region.area = deferred_area(polygons, {area});
  region.polygons = std::move(polygons);
  return region;
}

Region2 convex_region(const Ring2& ring) {
  Ring2 canonical = canonical_ring(ring);
  if (canonical.empty()) return {};
  return canonical_region({Polygon2{std::move(canonical), {}}});
}

}  // namespace penumbra
