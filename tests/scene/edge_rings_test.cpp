// The faces of coplanar triangles found from the mesh's edges (src/scene/edge_rings.h)
// against CGAL's Polygon_set_2 union of the same triangles, and the cases it must refuse.

#include <CGAL/Polygon_set_2.h>

#include <boost/test/unit_test.hpp>
#include <random>

#include "edge_rings.h"

namespace penumbra {
namespace {

using detail::edge_ring_faces;
using detail::EdgeRingFace;
using Triangles = std::vector<std::array<int, 3>>;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

Polygon ring_polygon(const std::vector<int>& ring, const std::vector<Point2>& points) {
  Polygon polygon;
  for (int v : ring) polygon.push_back(points[v]);
  return polygon;
}

// the oracle: the triangles united by Polygon_set_2.
std::vector<PolygonWithHoles> united(const Triangles& triangles,
                                     const std::vector<Point2>& points) {
  std::vector<Polygon> polygons;
  for (const auto& t : triangles) polygons.push_back(ring_polygon({t[0], t[1], t[2]}, points));
  PolygonSet set;
  set.join(polygons.begin(), polygons.end());
  std::vector<PolygonWithHoles> result;
  set.polygons_with_holes(std::back_inserter(result));
  return result;
}

// checks faces against the oracle: as many faces, each with as many holes as the oracle's
// piece it meets, the same point set (empty symmetric difference), and each face counting
// the triangles whose centroid lies in it.
void check_against_union(const std::vector<EdgeRingFace>& faces, const Triangles& triangles,
                         const std::vector<Point2>& points) {
  const auto oracle = united(triangles, points);
  BOOST_TEST(faces.size() == oracle.size());
  PolygonSet ours;
  for (const auto& face : faces) {
    PolygonWithHoles polygon(ring_polygon(face.outer, points));
    BOOST_TEST(polygon.outer_boundary().is_counterclockwise_oriented());
    for (const auto& hole : face.holes) {
      polygon.add_hole(ring_polygon(hole, points));
      BOOST_TEST(polygon.holes().back().is_clockwise_oriented());
    }
    for (const auto& piece : oracle)
      if (PolygonSet(piece).do_intersect(polygon))
        BOOST_TEST(face.holes.size() == piece.number_of_holes());
    std::size_t inside = 0;
    for (const auto& t : triangles) {
      const Point2 centroid = CGAL::centroid(points[t[0]], points[t[1]], points[t[2]]);
      int winding = detail::winding_number(polygon.outer_boundary().container(), centroid);
      for (const auto& hole : polygon.holes())
        winding += detail::winding_number(hole.container(), centroid);
      if (winding != 0) ++inside;
    }
    BOOST_TEST(face.triangles == inside);
    ours.join(polygon);
  }
  PolygonSet theirs;
  for (const auto& piece : oracle) theirs.join(piece);
  ours.symmetric_difference(theirs);
  BOOST_TEST(ours.is_empty());
}

// A grid of cells, each present or not, each cut along a random diagonal into two
// counter-clockwise triangles; the points sheared so that no edge is axis-aligned.
struct Grid {
  int size;
  std::vector<char> present;
  std::vector<Point2> points;
  Triangles triangles;

  int vertex(int i, int j) const { return j * (size + 1) + i; }
  bool cell(int i, int j) const {
    return i >= 0 && j >= 0 && i < size && j < size && present[j * size + i];
  }

  // true when some grid vertex has exactly two present cells around it, diagonally opposite:
  // there the union's boundary meets itself, which edge_ring_faces must refuse.
  bool touches_at_a_vertex() const {
    for (int j = 1; j < size; ++j)
      for (int i = 1; i < size; ++i) {
        const bool a = cell(i - 1, j - 1), b = cell(i, j - 1), c = cell(i - 1, j), d = cell(i, j);
        if (a + b + c + d == 2 && a == d) return true;
      }
    return false;
  }
};

Grid random_grid(std::mt19937& random, int size, double fill) {
  Grid grid{size, std::vector<char>(size * size), {}, {}};
  std::bernoulli_distribution keep(fill), diagonal(0.5);
  for (int j = 0; j <= size; ++j)
    for (int i = 0; i <= size; ++i) grid.points.emplace_back(i + 0.375 * j, j + 0.125 * i);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      if (!(grid.present[j * size + i] = keep(random))) continue;
      const int a = grid.vertex(i, j), b = grid.vertex(i + 1, j), c = grid.vertex(i + 1, j + 1),
                d = grid.vertex(i, j + 1);
      if (diagonal(random)) {
        grid.triangles.push_back({a, b, c});
        grid.triangles.push_back({a, c, d});
      } else {
        grid.triangles.push_back({a, b, d});
        grid.triangles.push_back({b, c, d});
      }
    }
  return grid;
}

BOOST_AUTO_TEST_CASE(random_grids_agree_with_the_polygon_set_union) {
  std::mt19937 random(20261202);
  std::size_t found = 0, refused = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Grid grid = random_grid(random, 2 + trial % 6, trial % 3 == 0 ? 0.9 : 0.6);
    if (grid.triangles.empty()) continue;
    const auto faces = edge_ring_faces(grid.triangles, grid.points);
    // Whole cells meet edge to edge, so the only refusal is a boundary touching itself.
    BOOST_TEST(faces.has_value() == !grid.touches_at_a_vertex(), "trial " << trial);
    if (!faces) {
      ++refused;
      continue;
    }
    ++found;
    check_against_union(*faces, grid.triangles, grid.points);
  }
  BOOST_TEST(found > 50u);  // both branches exercised
  BOOST_TEST(refused > 10u);
}

BOOST_AUTO_TEST_CASE(an_island_in_a_hole_is_a_second_face) {
  // A 4 x 4 square with a 2 x 2 hole (8 triangles), and a 1 x 1 island in the hole.
  const std::vector<Point2> points = {{0, 0},     {4, 0},     {4, 4},     {0, 4},  // outer 0-3
                                      {1, 1},     {3, 1},     {3, 3},     {1, 3},  // hole 4-7
                                      {1.5, 1.5}, {2.5, 1.5}, {2.5, 2.5}, {1.5, 2.5}};
  const Triangles triangles = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},  {2, 3, 7},
                               {2, 7, 6}, {3, 0, 4}, {3, 4, 7}, {8, 9, 10}, {8, 10, 11}};
  const auto faces = edge_ring_faces(triangles, points);
  BOOST_TEST_REQUIRE(faces.has_value());
  check_against_union(*faces, triangles, points);
  BOOST_TEST_REQUIRE(faces->size() == 2u);
  BOOST_TEST((*faces)[0].holes.size() + (*faces)[1].holes.size() == 1u);
}

BOOST_AUTO_TEST_CASE(overlaps_and_t_junctions_are_refused) {
  const std::vector<Point2> points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {1, 1}};
  // The same triangle twice: a directed edge used twice.
  BOOST_TEST(!edge_ring_faces({{0, 1, 2}, {0, 1, 2}}, points));
  // Two triangles overlapping without a common edge (their rings cross).
  BOOST_TEST(!edge_ring_faces({{0, 1, 2}, {0, 1, 3}}, points));
  // A T-junction: (0, 2, 3) above the diagonal, and below it (0, 4, 5), (4, 1, 5), (5, 1, 2),
  // which split the diagonal at 5: the boundary runs 0 -> 2 and back along 2 -> 5 -> 0.
  BOOST_TEST(!edge_ring_faces({{0, 2, 3}, {0, 4, 5}, {4, 1, 5}, {5, 1, 2}}, points));
  // The same square cut conformingly is one face of 4 triangles.
  const Triangles conforming = {{0, 5, 3}, {3, 5, 2}, {0, 4, 5}, {4, 1, 5}, {5, 1, 2}};
  const auto faces = edge_ring_faces(conforming, points);
  BOOST_TEST_REQUIRE(faces.has_value());
  check_against_union(*faces, conforming, points);
  BOOST_TEST((*faces)[0].triangles == 5u);
}

}  // namespace
}  // namespace penumbra
