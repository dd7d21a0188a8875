// Bicubic Bézier patches (issue #23): evaluation, derivatives, normals at collapsed edges,
// subdivision and the tessellation bound, against an independent evaluation (repeated
// linear interpolation, tests/support/de_casteljau.h) and sampling.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "penumbra/geometry/bezier_patch.h"
#include "support/de_casteljau.h"

namespace {

using penumbra::BezierPatch;
using penumbra::SplitMix64;
using penumbra::Vec3d;
using penumbra::test::casteljau_patch;
using penumbra::test::random_patch;

double distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3d unit(const Vec3d& a) {
  const double l = distance(a, {0, 0, 0});
  return {a[0] / l, a[1] / l, a[2] / l};
}

// A dome: the first row of control points collapsed to the apex (as the teapot's lid).
// S(u, v) = (u c(v), 1 - u^2) with c a cubic through angles 0 .. 1/2 rad: r = u has control
// values i/3 and u^2 has 0, 0, 1/3, 1 (degree elevation), so the apex is smooth with
// normal +z (S_u x S_v = (2u^2 c'_y, -2u^2 c'_x, u (c x c')_z), c turning counter-clockwise).
BezierPatch dome() {
  BezierPatch patch;
  const double height[] = {1, 1, 2.0 / 3, 0};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double r = i / 3.0, angle = 0.5 * j / 3.0;
      patch.points[4 * i + j] = {r * std::cos(angle), r * std::sin(angle), height[i]};
    }
  return patch;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bezier_patch)

BOOST_AUTO_TEST_CASE(points_and_derivatives_agree_with_de_casteljau) {
  SplitMix64 random(23);
  double worst_point = 0, worst_derivative = 0;
  for (int p = 0; p < 50; ++p) {
    const BezierPatch patch = random_patch(random);
    for (int k = 0; k < 40; ++k) {
      const double u = random.uniform(), v = random.uniform();
      const auto reference = casteljau_patch(patch, u, v);
      const BezierPatch::Jet jet = patch.jet(u, v);
      worst_point = std::max(worst_point, distance(jet.point, reference.point));
      worst_derivative = std::max(
          {worst_derivative, distance(jet.du, reference.du), distance(jet.dv, reference.dv)});
      BOOST_TEST(distance(patch.point(u, v), jet.point) == 0);
    }
  }
  BOOST_TEST(worst_point < 1e-14);
  BOOST_TEST(worst_derivative < 1e-13);
}

BOOST_AUTO_TEST_CASE(the_mixed_derivative_is_the_difference_quotient_of_the_slopes) {
  SplitMix64 random(7);
  const BezierPatch patch = random_patch(random);
  const double h = 1e-6;
  for (int k = 0; k < 20; ++k) {
    const double u = 0.1 + 0.8 * random.uniform(), v = 0.1 + 0.8 * random.uniform();
    const auto ahead = casteljau_patch(patch, u, v + h), behind = casteljau_patch(patch, u, v - h);
    const Vec3d duv = patch.jet(u, v).duv;
    for (int c = 0; c < 3; ++c)
      BOOST_TEST(std::abs(duv[c] - (ahead.du[c] - behind.du[c]) / (2 * h)) < 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(halves_are_the_same_surface) {
  SplitMix64 random(11);
  const BezierPatch patch = random_patch(random);
  for (const bool along_u : {true, false}) {
    const auto [first, second] = patch.split(along_u);
    for (int k = 0; k < 30; ++k) {
      const double s = random.uniform(), t = random.uniform();
      const Vec3d on_first = along_u ? patch.point(s / 2, t) : patch.point(t, s / 2);
      const Vec3d on_second = along_u ? patch.point(0.5 + s / 2, t) : patch.point(t, 0.5 + s / 2);
      BOOST_TEST(distance(first.point(along_u ? s : t, along_u ? t : s), on_first) < 1e-14);
      BOOST_TEST(distance(second.point(along_u ? s : t, along_u ? t : s), on_second) < 1e-14);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_normal_is_the_cross_product_of_the_slopes) {
  SplitMix64 random(5);
  const BezierPatch patch = random_patch(random);
  for (int k = 0; k < 30; ++k) {
    const double u = random.uniform(), v = random.uniform();
    const auto reference = casteljau_patch(patch, u, v);
    BOOST_TEST(distance(patch.normal(u, v), unit(cross(reference.du, reference.dv))) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(at_a_collapsed_edge_the_normal_is_the_limit_from_inside) {
  // The dome's row u = 0 is one point (the apex): S_v vanishes there. The limit of the
  // normal along u -> 0 is approached by the ordinary normal at small u.
  const BezierPatch patch = dome();
  for (double v : {0.0, 0.3, 0.7, 1.0}) {
    const Vec3d at_apex = patch.normal(0, v);
    const Vec3d near_apex = patch.normal(1e-7, v);
    BOOST_TEST(distance(at_apex, near_apex) < 1e-5);
    // The dome is smooth at its apex: the normal there is +z.
    BOOST_TEST(std::abs(at_apex[2] - 1) < 1e-12);
  }
  // The same patch with u reversed: the collapsed edge at u = 1, the normal still outward.
  BezierPatch reversed;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) reversed.points[4 * (3 - i) + j] = patch.at(i, j);
  for (double v : {0.0, 0.5, 1.0}) {
    BOOST_TEST(distance(reversed.normal(1, v), reversed.normal(1 - 1e-7, v)) < 1e-5);
    BOOST_TEST(std::abs(reversed.normal(1, v)[2] + 1) < 1e-12);  // S_u x S_v turned over
  }
}

BOOST_AUTO_TEST_CASE(the_tessellation_lies_within_its_tolerance) {
  // Sampled: on each triangle of the n x n grid (cut along (k, l)-(k+1, l+1)), the linear
  // interpolation of the corners against the surface at the same parameters.
  SplitMix64 random(1986);
  double worst_ratio = 0;
  for (int p = 0; p < 30; ++p) {
    const BezierPatch patch = random_patch(random, 2, 0.2 + random.uniform());
    const double tolerance = std::pow(10.0, -1 - 2 * random.uniform());
    const int n = penumbra::tessellation_segments(patch, tolerance);
    BOOST_TEST_REQUIRE(n >= 1);
    for (int sample = 0; sample < 2000; ++sample) {
      const int k = static_cast<int>(random.uniform() * n),
                l = static_cast<int>(random.uniform() * n);
      double a = random.uniform(), b = random.uniform();  // within the cell
      const bool lower = a >= b;  // the triangle (k,l) (k+1,l) (k+1,l+1) has a >= b
      const auto grid = [&](int i, int j) { return patch.point(double(i) / n, double(j) / n); };
      Vec3d linear;
      const Vec3d p00 = grid(k, l), p10 = grid(k + 1, l), p11 = grid(k + 1, l + 1),
                  p01 = grid(k, l + 1);
      for (int c = 0; c < 3; ++c)
        linear[c] = lower ? p00[c] + a * (p10[c] - p00[c]) + b * (p11[c] - p10[c])
                          : p00[c] + b * (p01[c] - p00[c]) + a * (p11[c] - p01[c]);
      const double error = distance(linear, patch.point((k + a) / n, (l + b) / n));
      worst_ratio = std::max(worst_ratio, error / tolerance);
    }
  }
  BOOST_TEST(worst_ratio <= 1.0);
  BOOST_TEST_MESSAGE("largest sampled error / tolerance: " << worst_ratio);
}

BOOST_AUTO_TEST_CASE(flatness_is_zero_on_a_bilinear_patch) {
  // Control points at the thirds of a bilinear patch (degree elevation) describe the
  // bilinear patch itself: a planar quadrilateral here.
  const Vec3d a{0, 0, 0}, b{2, 0, 1}, c{2.5, 1.5, 1.5}, d{0, 1, 0};
  BezierPatch patch;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double s = i / 3.0, t = j / 3.0;
      for (int k = 0; k < 3; ++k)
        patch.points[4 * i + j][k] =
            (1 - s) * (1 - t) * a[k] + s * (1 - t) * b[k] + s * t * c[k] + (1 - s) * t * d[k];
    }
  BOOST_TEST(patch.flatness() < 1e-15);
  BOOST_TEST(dome().flatness() > 0.1);
}

BOOST_AUTO_TEST_SUITE_END()
