#include "penumbra/shadow/region.h"

#include <algorithm>

#include "penumbra/base/parallel.h"
#include "penumbra/geometry/exact.h"
#include "penumbra/geometry/exact_sum.h"

namespace penumbra {
namespace {

bool point_less(const Point2& a, const Point2& b) {
  return CGAL::compare_xy(a, b) == CGAL::SMALLER;
}

bool ring_less(const Ring2& a, const Ring2& b) {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), point_less);
}

// returns twice the signed area of ring in rationals (the shoelace formula).
Rational twice_signed_area(const Ring2& ring) {
  Rational twice = 0;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const RationalPoint2& p = CGAL::exact(ring[k]);
    const RationalPoint2& q = CGAL::exact(ring[(k + 1) % n]);
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return twice;
}

}  // namespace

Exact signed_area(const Ring2& ring) {
  return exact_number(twice_signed_area(ring) / 2);
}

Ring2 canonical_ring(const Ring2& ring) {
  Ring2 out;
  for (const Point2& p : ring)
    if (out.empty() || out.back() != p) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  // Drop vertices whose neighbours are collinear with them, until none is left.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    for (std::size_t k = 0; k < out.size() && out.size() >= 3; ++k) {
      const std::size_t n = out.size();
      const Point2& before = out[(k + n - 1) % n];
      const Point2& after = out[(k + 1) % n];
      if (CGAL::collinear(before, out[k], after)) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
        changed = true;
        --k;
      }
    }
  }
  if (out.size() < 3) return {};
  std::rotate(out.begin(), std::min_element(out.begin(), out.end(), point_less), out.end());
  return out;
}

Region2 canonical_region(std::vector<Polygon2> polygons, std::optional<Exact> area) {
  Region2 region;
  // In rationals (no chain of lazy sums), each polygon on its own thread: a ground under a
  // city is one region of 10^4 polygons, whose areas are added when the exact total is
  // needed (exact_sum; adding them here one by one cost a gcd of the growing total each).
  std::vector<Rational> areas(area ? 0 : polygons.size());
  for_each_index(
      polygons.size(), polygons.size() > 64,
      [&](std::size_t k) {
        Polygon2& polygon = polygons[k];
        std::sort(polygon.holes.begin(), polygon.holes.end(), ring_less);
        if (area) return;
        Rational twice = twice_signed_area(polygon.outer);
        for (const Ring2& hole : polygon.holes) twice += twice_signed_area(hole);
        areas[k] = twice / 2;
      },
      16);
  if (area)
    region.area = std::move(*area);
  else if (areas.size() == 1)
    region.area = exact_number(std::move(areas.front()));
  else if (!areas.empty())
    region.area = exact_sum(std::move(areas));
  std::sort(polygons.begin(), polygons.end(),
            [](const Polygon2& a, const Polygon2& b) { return ring_less(a.outer, b.outer); });
  region.polygons = std::move(polygons);
  return region;
}

Region2 convex_region(const Ring2& ring) {
  Ring2 canonical = canonical_ring(ring);
  if (canonical.empty()) return {};
  return canonical_region({Polygon2{std::move(canonical), {}}});
}

}  // namespace penumbra
