// PROTOTYPE check: the pairwise arrangement against CGAL's (penumbra::coverage) on random
// regions of a square window: every count's region must be equal (canonical, exactly).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <CGAL/convex_hull_2.h>

#include "penumbra/shadow/region_overlay.h"
#include "segment_arrangement.h"

using namespace penumbra;

namespace {

constexpr long kWindow = 1L << 20;

long key_of(long count) { return count >= kWindow ? count - kWindow : -1; }

Region2 random_convex(std::mt19937& random, int mode) {
  std::vector<Point2> points;
  std::uniform_int_distribution<int> grid(0, 16);
  std::uniform_int_distribution<int> fine(0, 8 * 97);
  const int count = std::uniform_int_distribution<int>(3, 6)(random);
  for (int k = 0; k < count; ++k) {
    if (mode == 0)
      points.emplace_back(grid(random) / 2.0, grid(random) / 2.0);
    else
    {
      Rational x(fine(random), 97), y(fine(random), 97);
      x.canonicalize();
      y.canonicalize();
      points.push_back(point_from<Point2>(RationalPoint2(x, y)));
    }
  }
  std::vector<Point2> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull), Kernel());
  Ring2 ring = canonical_ring(Ring2(hull.begin(), hull.end()));
  if (ring.size() < 3) return {};
  return canonical_region({Polygon2{std::move(ring), {}}});
}

// the ring rotated to its smallest rotation (canonical_ring starts at the first smallest
// vertex, which a ring touching itself there has twice).
void normalize(Ring2& ring) {
  const auto less = [&](std::size_t a, std::size_t b) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto c = CGAL::compare_xy(ring[(a + k) % ring.size()], ring[(b + k) % ring.size()]);
      if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
    }
    return false;
  };
  std::size_t best = 0;
  for (std::size_t k = 1; k < ring.size(); ++k)
    if (less(k, best)) best = k;
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(best), ring.end());
}

void normalize(std::vector<Coverage>& parts) {
  for (Coverage& c : parts)
    for (Polygon2& p : c.region.polygons) {
      normalize(p.outer);
      for (Ring2& h : p.holes) normalize(h);
    }
}

}  // namespace

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::atoi(argv[1]) : 300;
  std::mt19937 random(20261207);
  const Polygon2 window{canonical_ring({Point2(0, 0), Point2(8, 0), Point2(8, 8), Point2(0, 8)}), {}};
  int failures = 0;
  double t_cgal = 0, t_new = 0;
  const int only = std::getenv("ONLY") ? std::atoi(std::getenv("ONLY")) : -1;
  for (int trial = 0; trial < trials; ++trial) {
    if (only >= 0 && trial == only) setenv("ARR_DEBUG", "1", 1); else unsetenv("ARR_DEBUG");
    std::vector<Region2> regions;
    const int count = std::uniform_int_distribution<int>(1, 12)(random);
    const int mode = trial % 3 == 2 ? 1 : 0;
    while (static_cast<int>(regions.size()) < count)
      if (Region2 r = random_convex(random, mode); !r.empty()) regions.push_back(std::move(r));
    std::vector<const Region2*> pointers;
    for (const Region2& r : regions) pointers.push_back(&r);
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<Coverage> reference = coverage(window, pointers);
    auto t1 = std::chrono::steady_clock::now();
    std::vector<proto::LayerSegment> segments;
    const auto add = [&](const Ring2& ring, long weight) {
      for (std::size_t i = 0; i < ring.size(); ++i)
        segments.push_back({ring[i], ring[(i + 1) % ring.size()], weight});
    };
    add(window.outer, kWindow);
    for (const Region2& r : regions)
      for (const Polygon2& p : r.polygons) {
        add(p.outer, 1);
        for (const Ring2& h : p.holes) add(h, 1);
      }
    const proto::SegmentArrangement arrangement = proto::arrange(segments);
    if (std::getenv("CHECK")) {
      std::size_t bad = 0;
      for (std::size_t h = 0; h < arrangement.origin.size(); h += 2)
        if (arrangement.count[arrangement.face[h + 1]] != arrangement.count[arrangement.face[h]] - arrangement.left[h / 2]) ++bad;
      std::size_t selfloop = 0;
      for (std::size_t h = 0; h < arrangement.origin.size(); h += 2)
        if (arrangement.face[h] == arrangement.face[h + 1]) ++selfloop;
      if (bad || trial == 1049)
        std::printf("trial %d: %zu faces, %zu edges, %zu inconsistent, %zu with one face both sides\n", trial, arrangement.faces, arrangement.origin.size() / 2, bad, selfloop);
    }
    auto parts = proto::polygons_by_count(arrangement, key_of);
    auto t2 = std::chrono::steady_clock::now();
    t_cgal += std::chrono::duration<double>(t1 - t0).count();
    t_new += std::chrono::duration<double>(t2 - t1).count();
    std::vector<Coverage> mine;
    for (auto& [k, polygons] : parts)
      if (Region2 region = canonical_region(std::move(polygons)); !region.empty())
        mine.push_back({static_cast<std::size_t>(k), std::move(region)});
    std::vector<Coverage> expected = reference;
    normalize(expected);
    normalize(mine);
    bool same = mine.size() == expected.size();
    for (std::size_t i = 0; same && i < mine.size(); ++i)
      same = mine[i].count == expected[i].count && mine[i].region == expected[i].region;
    if (!same) {
      ++failures;
      if (failures <= 2 && std::getenv("DUMP")) {
        const auto dump = [](const char* name, const std::vector<Coverage>& parts) {
          for (const Coverage& c : parts) {
            std::printf("%s count %zu:\n", name, c.count);
            for (const Polygon2& p : c.region.polygons) {
              std::printf("  outer");
              for (const Point2& q : p.outer) std::printf(" (%g,%g)", CGAL::to_double(q.x()), CGAL::to_double(q.y()));
              std::printf("\n");
              for (const Ring2& h : p.holes) {
                std::printf("  hole");
                for (const Point2& q : h) std::printf(" (%g,%g)", CGAL::to_double(q.x()), CGAL::to_double(q.y()));
                std::printf("\n");
              }
            }
          }
        };
        dump("cgal", reference);
        dump("mine", mine);
        for (const Region2& r : regions) {
          std::printf("region:");
          for (const Point2& q : r.polygons[0].outer) std::printf(" (%g,%g)", CGAL::to_double(q.x()), CGAL::to_double(q.y()));
          std::printf("\n");
        }
      }
      if (failures <= 5) {
        std::printf("trial %d (mode %d, %d regions): %zu parts against %zu\n", trial, mode, count,
                    mine.size(), reference.size());
        for (std::size_t i = 0; i < std::max(mine.size(), reference.size()); ++i)
          std::printf("  count %zu/%zu polygons %zu/%zu\n",
                      i < mine.size() ? mine[i].count : 999,
                      i < reference.size() ? reference[i].count : 999,
                      i < mine.size() ? mine[i].region.polygons.size() : 0,
                      i < reference.size() ? reference[i].region.polygons.size() : 0);
      }
    }
  }
  std::printf("%d trials, %d failures; CGAL %.3f s, pairwise %.3f s\n", trials, failures, t_cgal,
              t_new);
  return failures == 0 ? 0 : 1;
}
