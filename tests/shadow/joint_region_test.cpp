// Whether occluders may hide a linear source together on a face (src/shadow/joint_region.h,
// the test that lets the joint-umbra sweep leave out the region W): hand cases derived
// below, and random convex polygons with small integer coordinates (touching along edges
// and at vertices is frequent) against CGAL's Polygon_set_2 (region_set.h): the union over
// (a, b) of face ∩ PS1(a) ∩ PS2(b), minus the union of the umbrae, has positive area
// exactly when joint_parts finds polygons.

#include <boost/test/unit_test.hpp>

#include <random>

#include "half_plane.h"
#include "joint_region.h"
#include "region_set.h"
#include "support/heavy.h"

using namespace penumbra;
using detail::ConvexRing;
using detail::EndShadow;
using detail::FilteredAffine;

namespace {

// the functions <= 0 inside a counter-clockwise ring (one per edge, on its left).
EndShadow inside_of(const Ring2& ring) {
  EndShadow volume;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const RationalPoint2 a = CGAL::exact(ring[k]);
    const RationalPoint2 b = CGAL::exact(ring[(k + 1) % ring.size()]);
    volume.emplace_back(detail::Affine2{b.y() - a.y(), a.x() - b.x(),
                                        (b.x() - a.x()) * a.y() - (b.y() - a.y()) * a.x()});
  }
  return volume;
}

ConvexRing rational_ring(const Ring2& ring) {
  std::vector<RationalPoint2> points;
  for (const Point2& p : ring) points.push_back(CGAL::exact(p));
  return ConvexRing(std::move(points));
}

Ring2 rectangle(Exact x0, Exact y0, Exact x1, Exact y1) {
  return {Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)};
}

const Ring2 unit = rectangle(0, 0, 1, 1);

// The test's input: the first end hidden by the rings first[k] and the second by second[k]
// (an empty ring: that occluder hides nothing of that end), the umbrae, and the face.
struct Input {
  Input(const std::vector<Ring2>& first, const std::vector<Ring2>& second,
        const std::vector<Ring2>& umbrae, const Ring2& face)
      : piece(rational_ring(face)) {
    for (const Ring2& r : first) ends[0].push_back(r.empty() ? EndShadow{} : inside_of(r));
    for (const Ring2& r : second) ends[1].push_back(r.empty() ? EndShadow{} : inside_of(r));
    for (const Ring2& r : umbrae) rings.push_back(rational_ring(r));
  }
  std::array<std::vector<EndShadow>, 2> ends;
  std::vector<ConvexRing> rings;
  ConvexRing piece;
};

// joint_parts on that input.
std::vector<detail::EnclosedPolygon> parts(const std::vector<Ring2>& first,
                                           const std::vector<Ring2>& second,
                                           const std::vector<Ring2>& umbrae, const Ring2& face) {
  const Input in(first, second, umbrae, face);
  return detail::joint_parts(detail::FaceRegion(in.piece), in.ends, in.rings);
}

// whether W has interior on that face (the unit square unless one is given).
bool may(const std::vector<Ring2>& first, const std::vector<Ring2>& second,
         const std::vector<Ring2>& umbrae, const Ring2& face = unit) {
  return !parts(first, second, umbrae, face).empty();
}

// may_meet for the line through p with direction (dx, dy), its coefficients made exactly.
bool meets(const Point2& p, const Exact& dx, const Exact& dy,
           const std::vector<detail::EnclosedPolygon>& polygons) {
  const Exact d = dy, e = -dx, f = -(d * p.x() + e * p.y());
  return detail::may_meet({CGAL::to_interval(d), CGAL::to_interval(e), CGAL::to_interval(f)},
                          polygons);
}

// may_hide_together against Polygon_set_2 on random scenes whose points are the images by
// map of points with small integer coordinates.
template <class Map>
void agrees_with_polygon_set_2(const Map& map) {
  std::mt19937 random(17);  // fixed seed
  std::uniform_int_distribution<int> coordinate(0, 12);
  const Ring2 window = rectangle(0, 0, 12, 12);
  // a convex polygon of the window cut by one to three lines through grid points, or none.
  const auto polygon = [&]() -> Ring2 {
    Ring2 ring = window;
    for (int cut = 0; cut < 1 + coordinate(random) % 3 && ring.size() >= 3; ++cut) {
      const Point2 p(coordinate(random), coordinate(random)),
          q(coordinate(random), coordinate(random));
      if (p == q) continue;
      const Exact a = q.y() - p.y(), b = p.x() - q.x();
      ring = detail::clip(ring, {a, b, -(a * p.x() + b * p.y())});
    }
    const auto with_area = detail::ring_with_area(ring);
    if (!with_area) return Ring2{};
    Ring2 mapped;
    for (const Point2& p : *with_area) mapped.push_back(map(p));
    return mapped;
  };
  const Ring2 face = {map(Point2(1, 0)), map(Point2(12, 2)), map(Point2(10, 12)),
                      map(Point2(0, 9))};
  int yes = 0, no = 0, covered = 0, lines = 0;
  for (int iteration = 0; iteration < penumbra::test::samples(1000); ++iteration) {
    const std::size_t n = 2 + iteration % 3;
    std::vector<Ring2> first, second, umbrae;
    for (std::size_t k = 0; k < n; ++k) {
      first.push_back(polygon());
      second.push_back(polygon());
      umbrae.push_back(iteration % 2 ? polygon() : Ring2{});
    }
    // the oracle: the pairs' intersections with the face, united, minus the umbrae
    std::vector<Ring2> pairs, holes;
    for (const Ring2& a : first)
      for (const Ring2& b : second) {
        if (a.empty() || b.empty()) continue;
        Ring2 ring = detail::clip_to_convex(detail::clip_to_convex(face, a), b);
        if (const auto with_area = detail::ring_with_area(ring)) pairs.push_back(*with_area);
      }
    for (const Ring2& u : umbrae)
      if (!u.empty()) holes.push_back(u);
    const Region2 w = detail::unite_minus(pairs, holes);
    const bool expected = !w.empty() && CGAL::is_positive(w.area);
    const auto found = parts(first, second, umbrae, face);
    BOOST_TEST(!found.empty() == expected, "iteration " << iteration);
    // No line through a corner of W (in its closure) is said to miss the parts: the sweep
    // keeps every line that can pass through W. A line beyond the face misses them.
    for (const Polygon2& part : w.polygons)
      for (const Point2& corner : part.outer)
        for (const auto& [dx, dy] : {std::pair<int, int>{1, 0}, {0, 1}, {1, 1}, {2, -1}}) {
          BOOST_TEST(meets(corner, dx, dy, found), "iteration " << iteration);
          ++lines;
        }
    if (!found.empty()) {
      const Point2 far = map(Point2(20, 20));
      BOOST_TEST(!meets(far, 1, -1, found), "iteration " << iteration);
    }
    (expected ? yes : no) += 1;
    if (!expected && !pairs.empty()) ++covered;
  }
  BOOST_TEST_MESSAGE("may " << yes << ", may not " << no << " (" << covered
                            << " covered by umbrae)");
  // both answers occur, and umbrae cover overlapping pairs often enough to be tested
  BOOST_TEST(yes >= penumbra::test::samples(100));
  BOOST_TEST(no >= penumbra::test::samples(100));
  BOOST_TEST(covered >= penumbra::test::samples(50));
  BOOST_TEST(lines >= penumbra::test::samples(400));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(joint_region)

BOOST_AUTO_TEST_CASE(hand_cases) {
  const Exact half(Exact(1) / 2);
  const auto strip = [](Exact x0, Exact x1) { return rectangle(x0, -1, x1, 2); };
  // a hides end 1 on x <= 0.6, b end 2 on x >= 0.4: the strip 0.4 < x < 0.6 has interior.
  BOOST_TEST(may({strip(-1, Exact(6) / 10), {}}, {{}, strip(Exact(4) / 10, 2)}, {}));
  // ... unless an umbra holds the strip: one umbra, or two that meet at x = 0.5.
  BOOST_TEST(!may({strip(-1, Exact(6) / 10), {}}, {{}, strip(Exact(4) / 10, 2)},
                  {strip(Exact(3) / 10, Exact(7) / 10)}));
  BOOST_TEST(!may({strip(-1, Exact(6) / 10), {}}, {{}, strip(Exact(4) / 10, 2)},
                  {strip(Exact(3) / 10, half), strip(half, Exact(7) / 10)}));
  // two umbrae with a gap 0.5 < x < 0.55 between them leave interior points.
  BOOST_TEST(may({strip(-1, Exact(6) / 10), {}}, {{}, strip(Exact(4) / 10, 2)},
                 {strip(Exact(3) / 10, half), strip(Exact(55) / 100, Exact(7) / 10)}));
  // an umbra across the strip only for y < 0.5 leaves its upper half.
  BOOST_TEST(may({strip(-1, Exact(6) / 10), {}}, {{}, strip(Exact(4) / 10, 2)},
                 {rectangle(0, -1, 1, half)}));
  // point shadows that only touch along x = 0.5 share no interior point.
  BOOST_TEST(!may({strip(-1, half), {}}, {{}, strip(half, 2)}, {}));
  // ... nor do those that overlap outside the face (x > 1).
  BOOST_TEST(!may({strip(-1, 3), {}}, {{}, strip(Exact(11) / 10, 2)}, {}));
  // one occluder hiding both ends: its umbra, left out when the ring given holds it ...
  BOOST_TEST(!may({strip(Exact(2) / 10, Exact(4) / 10)}, {strip(Exact(1) / 10, half)},
                  {strip(Exact(2) / 10, Exact(4) / 10)}));
  // ... and kept when the ring given is smaller (a source clipped after the umbrae).
  BOOST_TEST(may({strip(Exact(2) / 10, Exact(4) / 10)}, {strip(Exact(1) / 10, half)},
                 {strip(Exact(25) / 100, Exact(4) / 10)}));
  // an occluder that hides nothing of an end takes no part.
  BOOST_TEST(!may({{}, {}}, {strip(-1, 2), strip(-1, 2)}, {}));
  // strips that overlap by 1e-30 around x = 1/2 or 1/3 (closer than any interval of
  // doubles tells): a sliver of interior, decided in rationals; apart by as much: none.
  const Exact tiny(Rational("1/1000000000000000000000000000000"));
  for (const Exact& x : {half, Exact(1) / 3}) {
    BOOST_TEST(may({strip(-1, x + tiny), {}}, {{}, strip(x, 2)}, {}));
    BOOST_TEST(!may({strip(-1, x - tiny), {}}, {{}, strip(x, 2)}, {}));
    // ... and an umbra that stops 1e-30 short of the sliver's far side leaves some of it.
    BOOST_TEST(!may({strip(-1, x + tiny), {}}, {{}, strip(x, 2)}, {strip(0, x + tiny)}));
    BOOST_TEST(may({strip(-1, x + tiny), {}}, {{}, strip(x, 2)}, {strip(0, x + tiny / 2)}));
  }
}

// Points with small integer coordinates: their intervals are exact, and so are the signs at
// the given corners, ties included.
BOOST_AUTO_TEST_CASE(agrees_with_polygon_set_2_on_a_grid) {
  agrees_with_polygon_set_2([](const Point2& p) { return p; });
}

// The same scenes through a map with thirds, fifths and sevenths (orientation kept: its
// determinant 1/21 - 1/315 is positive), so that no coordinate is a double: the intervals
// cannot certify the ties, and the rationals decide them.
BOOST_AUTO_TEST_CASE(agrees_with_polygon_set_2_off_the_doubles) {
  agrees_with_polygon_set_2(
      [](const Point2& p) { return Point2(p.x() / 7 + p.y() / 21, p.x() / 15 + p.y() / 3); });
}

BOOST_AUTO_TEST_SUITE_END()
