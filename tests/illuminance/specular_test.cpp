#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/specular.h"

// Phong's specular term (a luminance, cd/m^2) for point sources and, as Nishita 1985 section
// 4.2.1 suggests, for a linear source treated as a series of point sources. Expected values:
// hand-computed mirror geometry, and a brute-force sum over a million point sources.

namespace {

using penumbra::Vec3d;
using penumbra::illuminance::linear_specular;
using penumbra::illuminance::PhongSpecular;
using penumbra::illuminance::point_specular;

using penumbra::pi;

double dot(const Vec3d& p, const Vec3d& q) {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
Vec3d unit(const Vec3d& v) {
  const double l = std::sqrt(dot(v, v));
  return {v[0] / l, v[1] / l, v[2] / l};
}

// sums Phong's term of `elements` point sources of intensity I sin(theta) dl at the
// midpoints of equal pieces of the tube a -> b (the paper's "series of point sources").
double brute_force(const Vec3d& p, const Vec3d& n, const Vec3d& to_viewer, const Vec3d& a,
                   const Vec3d& b, double intensity, const PhongSpecular& m, int elements,
                   double u0 = 0, double u1 = 1) {
  const Vec3d along{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double tube_length = std::sqrt(dot(along, along));
  const Vec3d axis = unit(along);
  const double dl = (u1 - u0) * tube_length / elements;
  double sum = 0;
  for (int i = 0; i < elements; ++i) {
    const double u = u0 + (u1 - u0) * (i + 0.5) / elements;
    const Vec3d v{a[0] + u * along[0] - p[0], a[1] + u * along[1] - p[1],
                  a[2] + u * along[2] - p[2]};
    const double r2 = dot(v, v);
    const Vec3d l = unit(v);
    const double cos_alpha = dot(n, l);
    if (cos_alpha <= 0 || dot(n, to_viewer) <= 0) continue;
    const double cos_theta = dot(l, axis);
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const Vec3d mirror{2 * cos_alpha * n[0] - l[0], 2 * cos_alpha * n[1] - l[1],
                       2 * cos_alpha * n[2] - l[2]};
    const double cos_psi = dot(mirror, to_viewer);
    if (cos_psi <= 0) continue;
    sum += m.specular / pi * intensity * sin_theta * dl / r2 * std::pow(cos_psi, m.shininess);
  }
  return sum;
}

bool close(double value, double expected, double relative) {
  return std::abs(value - expected) <= relative * std::abs(expected);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(specular)

BOOST_AUTO_TEST_CASE(point_source_follows_phong) {
  const PhongSpecular m{0.4, 20};
  // Lamp at (-1, 0, 1), r^2 = 2; seen in the mirror direction (1, 0, 1)/sqrt(2) cos(psi) = 1:
  // L = (0.4 / pi) * 100 / 2.
  const double mirror = point_specular({0, 0, 0}, {0, 0, 1}, unit({1, 0, 1}), {-1, 0, 1}, 100, m);
  BOOST_TEST(close(mirror, 0.4 / pi * 50, 1e-13));
  // Seen from straight above, cos(psi) = 1 / sqrt(2).
  const double above = point_specular({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {-1, 0, 1}, 100, m);
  BOOST_TEST(close(above, 0.4 / pi * 50 * std::pow(0.5, 10), 1e-14));
  // No highlight when the lamp or the viewer is behind, or psi >= 90 degrees.
  BOOST_TEST(point_specular({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {-1, 0, -1}, 100, m) == 0.0);
  BOOST_TEST(point_specular({0, 0, 0}, {0, 0, 1}, {0, 0, -1}, {-1, 0, 1}, 100, m) == 0.0);
  BOOST_TEST(point_specular({0, 0, 0}, {0, 0, 1}, unit({-1, 0, 0.2}), {-1, 0, 1}, 100, m) == 0.0);
}

BOOST_AUTO_TEST_CASE(linear_source_equals_a_series_of_point_sources) {
  struct Case {
    Vec3d p, n, to_viewer, a, b;
    PhongSpecular material;
  };
  const Case cases[] = {
      // Ceiling tube over a glossy floor, viewer near the mirror direction.
      {{0, 0, 0}, {0, 0, 1}, unit({-1, -0.2, 1.1}), {0.5, -1, 2.5}, {1.5, 1, 2.5}, {0.3, 30}},
      // Oblique tube, a broad lobe.
      {{0.2, 0.1, 0}, unit({0.1, 0, 1}), unit({0.4, 0.5, 1}), {-1, -1, 1}, {0.5, 0.3, 2}, {0.5, 2}},
      // A sharp highlight (n = 400).
      {{0, 0, 0}, {0, 0, 1}, unit({-1, 0, 1}), {0.5, -2, 0.5}, {1.5, 2, 1.5}, {0.9, 400}},
      // A tube crossing the receiving plane.
      {{0, 0, 0}, {0, 0, 1}, unit({-1, 0.3, 1}), {1, -1, -1}, {1, 1, 2}, {0.5, 8}},
  };
  for (const Case& c : cases) {
    const double value = linear_specular(c.p, c.n, c.to_viewer, c.a, c.b, 150, c.material);
    const double expected = brute_force(c.p, c.n, c.to_viewer, c.a, c.b, 150, c.material, 1000000);
    BOOST_TEST(value > 0);
    BOOST_TEST(close(value, expected, 2e-6), value << " vs " << expected);
  }
}

BOOST_AUTO_TEST_CASE(visible_parts_only) {
  const Vec3d p{0, 0, 0}, n{0, 0, 1}, to_viewer = unit({-1, -0.2, 1.1});
  const Vec3d a{0.5, -1, 2.5}, b{1.5, 1, 2.5};
  const PhongSpecular m{0.3, 30};
  const double parts = linear_specular(p, n, to_viewer, a, b, 150, m, {{0.1, 0.35}, {0.6, 0.8}});
  const double expected = brute_force(p, n, to_viewer, a, b, 150, m, 400000, 0.1, 0.35) +
                          brute_force(p, n, to_viewer, a, b, 150, m, 400000, 0.6, 0.8);
  BOOST_TEST(close(parts, expected, 1e-6));
  BOOST_TEST(linear_specular(p, n, {0, 0, -1}, a, b, 150, m) == 0.0);       // viewer behind
  BOOST_TEST(linear_specular(p, n, to_viewer, a, b, 150, {0, 30}) == 0.0);  // k_s = 0
}

BOOST_AUTO_TEST_SUITE_END()
