// The fast paths for points given as doubles agree with the exact-kernel constructions:
// the small hull (src/geometry/small_hull.*) with CGAL's hull in the exact kernel, and
// the dyadic planes (geometry/dyadic_plane.h) with CGAL's Plane_3 constructors,
// coefficient by coefficient.

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <random>

#include "penumbra/geometry/convex_polyhedron.h"
#include "penumbra/geometry/dyadic_plane.h"
#include "penumbra/geometry/geometry_error.h"

using namespace penumbra;

namespace {

// returns p with the same value, but as a lazy construction (x / 3 * 3): its interval is
// not a single double, so ConvexPolyhedron::hull takes the exact-kernel path.
Point3 not_a_double(const Point3& p) {
  const Exact three(3);
  return Point3(p.x() / three * three, p.y() / three * three, p.z() / three * three);
}

void check_same_solid(const ConvexPolyhedron& fast, const ConvexPolyhedron& exact) {
  BOOST_TEST(fast.vertices() == exact.vertices());
  BOOST_TEST_REQUIRE(fast.faces().size() == exact.faces().size());
  for (std::size_t f = 0; f < fast.faces().size(); ++f) {
    const Face& a = fast.faces()[f];
    const Face& b = exact.faces()[f];
    BOOST_TEST(a.vertices == b.vertices);
    BOOST_TEST(a.neighbours == b.neighbours);
    BOOST_TEST(CGAL::exact(a.plane) == CGAL::exact(b.plane));
    BOOST_TEST(a.ring == b.ring);
    BOOST_TEST(a.area == b.area);
  }
}

// the plane's exact coefficients a, b, c, d as stored (not up to scale).
std::array<Exact::ET, 4> coefficients(const Plane3& plane) {
  const auto& p = CGAL::exact(plane);
  return {p.a(), p.b(), p.c(), p.d()};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(double_paths)

BOOST_AUTO_TEST_CASE(small_hull_equals_the_exact_kernel_hull) {
  // Fixed seed. Lattice points in {-2..2}^3 make coplanar faces, collinear edges, interior
  // and repeated points; rotated boxes (full doubles) are the city's buildings.
  std::mt19937 random(20261201);
  std::uniform_int_distribution<int> lattice(-2, 2), count(4, 12);
  std::uniform_real_distribution<double> angle(0, 3.14159), size(0.5, 5);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Point3> points;
    if (trial % 3 == 2) {
      const double c = std::cos(angle(random)), s = std::sin(angle(random));
      const double w = size(random), d = size(random), h = size(random);
      for (int k = 0; k < 8; ++k) {
        const double x = (k & 1 ? w : -w), y = (k & 2 ? d : -d);
        points.emplace_back(10 + c * x - s * y, 20 + s * x + c * y, k & 4 ? h : 0.0);
      }
    } else {
      const int n = count(random);
      for (int i = 0; i < n; ++i)
        points.emplace_back(lattice(random), lattice(random), lattice(random));
    }
    std::vector<Point3> lazy;
    for (const Point3& p : points) lazy.push_back(not_a_double(p));
    ConvexPolyhedron fast;
    try {
      fast = ConvexPolyhedron::hull(points);
    } catch (const GeometryError&) {
      BOOST_CHECK_THROW(ConvexPolyhedron::hull(lazy), GeometryError);
      continue;
    }
    check_same_solid(fast, ConvexPolyhedron::hull(lazy));
    ++compared;
  }
  BOOST_TEST(compared > 200);
}

BOOST_AUTO_TEST_CASE(dyadic_planes_equal_cgal_planes_coefficient_by_coefficient) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-100, 100);
  const auto point = [&] {
    return Double3{coordinate(random), coordinate(random), coordinate(random)};
  };
  const auto exact = [](const Double3& x) { return Point3(x[0], x[1], x[2]); };
  for (int trial = 0; trial < 200; ++trial) {
    const Double3 p = point(), q = point(), r = point(), inside = point();
    // CGAL's constructions, lazily: Plane3(p, q, r) and Plane3(p, (q - p) x r).
    Plane3 through(exact(p), exact(q), exact(r));
    if (through.oriented_side(exact(inside)) == CGAL::ON_POSITIVE_SIDE)
      through = through.opposite();
    const Vector3 direction(r[0], r[1], r[2]);
    Plane3 along(exact(p), CGAL::cross_product(exact(q) - exact(p), direction));
    if (along.oriented_side(exact(inside)) == CGAL::ON_POSITIVE_SIDE) along = along.opposite();
    const auto fast_through = oriented_plane(p, q, r, inside);
    const auto fast_along = oriented_plane_along(p, q, r, inside);
    BOOST_TEST_REQUIRE(fast_through.has_value());
    BOOST_TEST_REQUIRE(fast_along.has_value());
    BOOST_TEST(coefficients(*fast_through) == coefficients(through));
    BOOST_TEST(coefficients(*fast_along) == coefficients(along));
  }
  // Degenerate: collinear points, and an edge parallel to the direction.
  BOOST_TEST(!oriented_plane({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 1}).has_value());
  BOOST_TEST(!oriented_plane_along({0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {0, 0, 1}).has_value());
}

BOOST_AUTO_TEST_SUITE_END()
