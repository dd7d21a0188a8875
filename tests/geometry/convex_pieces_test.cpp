// Faces cut into convex pieces (geometry/convex_pieces.h), checked against the polygon
// itself: the pieces are strictly convex, counter-clockwise seen from the plane's positive
// side, use only the rings' points, their areas add up to the polygon's (exact shoelace
// sums), and random rational points of the plane lie inside the polygon exactly when they
// lie inside one piece — an exact oracle that needs no triangulation.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <memory>
#include <set>
#include <thread>

#include "penumbra/base/random.h"
#include "penumbra/geometry/convex_pieces.h"

using namespace penumbra;

namespace {

using Ring = std::vector<Point3>;

// The polygon in the plane z = h given by xy rings, or turned into a slanted plane by
// (x, y) -> (x, y, x + 2y + h) when slanted (the pieces are then checked in the xy shadow).
struct Case {
  const char* name;
  std::vector<std::array<double, 2>> outer;               // counter-clockwise
  std::vector<std::vector<std::array<double, 2>>> holes;  // clockwise
};

Point3 lift(const std::array<double, 2>& p, bool slanted) {
  return Point3(p[0], p[1], slanted ? p[0] + 2 * p[1] + 1 : 1);
}

// returns the case's outer ring and holes, lifted.
std::pair<Ring, std::vector<Ring>> lifted(const Case& c, bool slanted) {
  std::pair<Ring, std::vector<Ring>> rings;
  for (const auto& p : c.outer) rings.first.push_back(lift(p, slanted));
  for (const auto& hole : c.holes) {
    rings.second.emplace_back();
    for (const auto& p : hole) rings.second.back().push_back(lift(p, slanted));
  }
  return rings;
}

Point2 flat(const Point3& p) {
  return Point2(p.x(), p.y());
}

Exact twice_area(const std::vector<Point2>& ring) {
  Exact sum = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % ring.size()];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

// -1 outside, 0 on the boundary, 1 inside a simple ring (crossing number, exact).
int side_of_ring(const std::vector<Point2>& ring, const Point2& q) {
  bool inside = false;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % ring.size()];
    if (CGAL::orientation(a, b, q) == CGAL::COLLINEAR &&
        CGAL::collinear_are_ordered_along_line(a, q, b))
      return 0;
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        CGAL::orientation(a, b, q) == (b.y() > a.y() ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN))
      inside = !inside;
  }
  return inside ? 1 : -1;
}

const std::vector<Case> cases = {
    {"square", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}},
    {"L", {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}, {}},
    {"comb",
     {{0, 0},
      {7, 0},
      {7, 3},
      {6, 3},
      {6, 1},
      {5, 1},
      {5, 3},
      {4, 3},
      {4, 1},
      {3, 1},
      {3, 3},
      {2, 3},
      {2, 1},
      {1, 1},
      {1, 3},
      {0, 3}},
     {}},
    {"window wall", {{0, 0}, {6, 0}, {6, 3}, {0, 3}}, {{{2, 1}, {2, 2.2}, {4, 2.2}, {4, 1}}}},
    {"two holes",
     {{0, 0}, {9, 0}, {9, 5}, {0, 5}},
     {{{1, 1}, {1, 4}, {3, 4}, {3, 1}}, {{5, 1}, {6.5, 4}, {8, 1}}}},
    {"hole touching the outer ring",
     {{0, 0}, {6, 0}, {6, 6}, {0, 6}},
     {{{3, 0}, {2, 2}, {4, 2}}}},  // the hole's corner (3, 0) lies inside the outer ring's edge
    {"star", {{0, 0}, {3, 1}, {6, 0}, {5, 3}, {6, 6}, {3, 5}, {0, 6}, {1, 3}}, {}},
};

}  // namespace

BOOST_AUTO_TEST_SUITE(convex_pieces_suite)

BOOST_AUTO_TEST_CASE(pieces_tile_the_polygon_exactly) {
  SplitMix64 random(14);
  for (const Case& c : cases)
    for (bool slanted : {false, true}) {
      BOOST_TEST_CONTEXT(c.name << (slanted ? " (slanted)" : "")) {
        const auto [outer, holes] = lifted(c, slanted);
        const Plane3 plane(outer[0], outer[1], outer[outer.size() - 1]);  // corner at (0,0) convex
        BOOST_TEST_REQUIRE(CGAL::is_positive(plane.c()));  // seen from above: counter-clockwise

        const auto pieces = convex_pieces(plane, outer, holes);
        std::set<Point3> ring_points(outer.begin(), outer.end());
        for (const Ring& hole : holes) ring_points.insert(hole.begin(), hole.end());

        std::vector<std::vector<Point2>> flat_pieces;
        Exact pieces_area = 0;
        for (const Ring& piece : pieces) {
          std::vector<Point2> ring;
          for (const Point3& p : piece) {
            BOOST_TEST(plane.has_on(p));
            BOOST_TEST(ring_points.count(p) == 1u);  // no new points
            ring.push_back(flat(p));
          }
          // Convex and counter-clockwise: no right turn anywhere.
          for (std::size_t k = 0; k < ring.size(); ++k)
            BOOST_TEST(CGAL::orientation(ring[k], ring[(k + 1) % ring.size()],
                                         ring[(k + 2) % ring.size()]) != CGAL::RIGHT_TURN);
          BOOST_TEST(CGAL::is_positive(twice_area(ring)));
          pieces_area += twice_area(ring);
          flat_pieces.push_back(std::move(ring));
        }
        std::vector<Point2> flat_outer;
        for (const Point3& p : outer) flat_outer.push_back(flat(p));
        Exact polygon_area = twice_area(flat_outer);
        std::vector<std::vector<Point2>> flat_holes;
        for (const Ring& hole : holes) {
          flat_holes.emplace_back();
          for (const Point3& p : hole) flat_holes.back().push_back(flat(p));
          polygon_area += twice_area(flat_holes.back());  // clockwise: negative
        }
        BOOST_TEST((pieces_area == polygon_area));

        // Points on a 1/64 grid (so many fall on edges and are skipped) and random ones.
        std::size_t inside = 0, compared = 0;
        for (int k = 0; k < 3000; ++k) {
          const Point2 q(std::floor(random.uniform() * 12 * 64 - 64) / 64,
                         std::floor(random.uniform() * 12 * 64 - 64) / 64);
          int in_polygon = side_of_ring(flat_outer, q);
          for (const auto& hole : flat_holes) {
            const int in_hole = side_of_ring(hole, q);
            if (in_hole == 0) in_polygon = 0;
            if (in_hole == 1 && in_polygon == 1) in_polygon = -1;
          }
          int in_pieces = 0;
          bool on_piece_boundary = false;
          for (const auto& piece : flat_pieces) {
            const int side = side_of_ring(piece, q);
            on_piece_boundary = on_piece_boundary || side == 0;
            in_pieces += side == 1;
          }
          if (in_polygon == 0 || on_piece_boundary) continue;
          ++compared;
          inside += in_polygon == 1;
          BOOST_TEST(in_pieces == (in_polygon == 1 ? 1 : 0));
        }
        BOOST_TEST(inside > 100u);
        BOOST_TEST(compared - inside > 100u);
      }
    }
}

BOOST_AUTO_TEST_CASE(convex_faces_stay_whole_and_reflex_corners_need_pieces) {
  // Hertel-Mehlhorn merging keeps a convex face whole and gives an L (one reflex corner) two
  // pieces. The comb has 6 reflex corners; each needs a diagonal and a diagonal serves at
  // most two, so at least 3 diagonals and 4 pieces. A diagonal the greedy merge keeps would
  // make a reflex angle at one of its ends, a reflex corner of the comb, and a corner has
  // at most two such diagonals: at most 12 diagonals, 13 pieces (2r + 1).
  const auto count = [](const Case& c) {
    Ring outer;
    for (const auto& p : c.outer) outer.push_back(lift(p, false));
    return convex_pieces(Plane3(0, 0, 1, -1), outer, {}).size();
  };
  BOOST_TEST(count(cases[0]) == 1u);
  BOOST_TEST(count(cases[1]) == 2u);
  BOOST_TEST(count(cases[2]) >= 4u);
  BOOST_TEST(count(cases[2]) <= 13u);
}

BOOST_AUTO_TEST_CASE(pieces_depend_on_the_polygon_not_on_where_its_rings_start) {
  // A rectangle with two holes, given with every ring rotated and the holes swapped, then an
  // octagon (cocircular points: many Delaunay triangulations) rotated: the same pieces, in
  // the same order.
  const Case& c = cases[4];
  const auto [outer, holes] = lifted(c, true);
  const Plane3 plane(outer[0], outer[1], outer[3]);
  const auto pieces = convex_pieces(plane, outer, holes);
  for (std::size_t shift = 1; shift < outer.size(); ++shift) {
    Ring rotated = outer;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(shift),
                rotated.end());
    std::vector<Ring> swapped(holes.rbegin(), holes.rend());
    for (Ring& hole : swapped)
      std::rotate(hole.begin(), hole.begin() + static_cast<std::ptrdiff_t>(shift % hole.size()),
                  hole.end());
    BOOST_TEST((convex_pieces(plane, rotated, swapped) == pieces), "shift " << shift);
  }
  Ring octagon;
  for (const auto& p : std::vector<std::array<double, 2>>{
           {2, 0}, {4, 0}, {6, 2}, {6, 4}, {4, 6}, {2, 6}, {0, 4}, {0, 2}})
    octagon.push_back(lift(p, false));
  const Plane3 flat_plane(0, 0, 1, -1);
  const auto octagon_pieces = convex_pieces(flat_plane, octagon, {});
  BOOST_TEST(octagon_pieces.size() == 1u);  // convex: whole, whichever triangulation
  for (std::size_t shift = 1; shift < octagon.size(); ++shift) {
    Ring rotated = octagon;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(shift),
                rotated.end());
    BOOST_TEST((convex_pieces(flat_plane, rotated, {}) == octagon_pieces));
  }
}

BOOST_AUTO_TEST_CASE(pieces_do_not_depend_on_the_heap_or_the_thread) {
  // A face of the IFC house (fixtures/meshes/AC14-FZK-Haus.ifc.gz: a window frame with two
  // panes, x = 11.88, here (y, z)): rectilinear, so full of cocircular quadruples, where a
  // constrained Delaunay triangulation's flips follow the order of its faces' addresses
  // (the house gave 5 or 6 pieces from run to run). The pieces must be the same after other
  // allocations and in other threads.
  const Case frame{"window frame",
                   {{6.5023937225341797, 0.80000019073486328},
                    {6.5723934173583984, 0.80000019073486328},
                    {7.4673938751220703, 0.79999923706054688},
                    {8.5023937225341797, 0.79999923706054688},
                    {8.5023937225341797, 2},
                    {6.5023937225341797, 2}},
                   {{{7.4673938751220703, 1.9299993515014648},
                     {7.4673938751220703, 0.86999988555908203},
                     {6.5723934173583984, 0.86999988555908203},
                     {6.5723934173583984, 1.9299993515014648}},
                    {{8.4323940277099609, 1.9299993515014648},
                     {8.4323940277099609, 0.86999988555908203},
                     {7.5373935699462891, 0.86999988555908203},
                     {7.5373935699462891, 1.9299993515014648}}}};
  // As in the file: in the plane x = 11.88 (rounded to float), (y, z) from the case.
  const double x = 11.880000114440918;
  const auto place = [&](const std::array<double, 2>& p) { return Point3(x, p[0], p[1]); };
  Ring outer;
  std::vector<Ring> holes;
  for (const auto& p : frame.outer) outer.push_back(place(p));
  for (const auto& hole : frame.holes) {
    holes.emplace_back();
    for (const auto& p : hole) holes.back().push_back(place(p));
  }
  const Plane3 plane(1, 0, 0, -x);
  const auto reference = convex_pieces(plane, outer, holes);
  // Other heaps: blocks of other sizes allocated first, here and in fresh threads.
  const auto after_allocations = [&](int round) {
    std::vector<std::unique_ptr<char[]>> other;
    for (int k = 0; k < 331 * round; ++k) other.emplace_back(new char[24 + (k % 7) * 40]);
    return convex_pieces(plane, outer, holes);
  };
  for (int round = 1; round <= 12; ++round) {
    BOOST_TEST((after_allocations(round) == reference), "after allocations, round " << round);
    std::vector<std::vector<Point3>> there;
    std::thread([&] { there = after_allocations(round); }).join();
    BOOST_TEST((there == reference), "in another thread, round " << round);
  }
}

BOOST_AUTO_TEST_SUITE_END()
