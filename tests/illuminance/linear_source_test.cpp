#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "penumbra/base/numbers.h"
#include "penumbra/illuminance/linear_source.h"
#include "reference_quadrature.h"

// Checks of the linear-source kernels (Nishita 1985 section 4.2.1, eqs. (5)-(8)). Expected
// values come from (1) the paper's Case A and Case B special forms, re-derived below with
// their misprints corrected, (2) an adaptive Gauss-Kronrod (61-point, Boost.Math) integration
// of eq. (5) written here from the paper's definitions, and (3) flux conservation.

namespace {

using penumbra::Vec3d;
using penumbra::illuminance::linear_illuminance;
using penumbra::illuminance::linear_illuminance_quadrature;
using penumbra::illuminance::outer_side_interval;
using penumbra::illuminance::SourceInterval;

using penumbra::pi;

using namespace penumbra::vector_ops;

double relative_difference(double value, double expected) {
  if (value == expected) return 0;
  return std::abs(value - expected) / std::abs(expected);
}

// integrates eq. (5), E = I * integral of sin(theta) cos(beta) / r^2 dl, over the part of
// [u0, u1] on the outer side of the receiving plane, with theta the angle between PQ and
// the source and beta the angle between PQ and N (Fig. 8a). The integrand peaks at the foot
// of the perpendicular with width h, so the interval is broken there and at foot +- h 10^k.
double reference_illuminance(const Vec3d& p, const Vec3d& n, const Vec3d& a, const Vec3d& b,
                             double intensity, double u0 = 0, double u1 = 1) {
  const Vec3d along = b - a;
  const double source_length = length(along);
  const Vec3d d = normalized(along);
  // Receiving plane crossing (Fig. 7, S3), found from the signed distances of the ends.
  const double fa = dot(n, a - p);
  const double fb = dot(n, b - p);
  double lo = u0, hi = u1;
  if (fa <= 0 && fb <= 0) return 0;
  if (fa <= 0) lo = std::max(lo, fa / (fa - fb));
  if (fb <= 0) hi = std::min(hi, fa / (fa - fb));
  if (!(hi > lo)) return 0;
  auto integrand = [&](double s) {
    const Vec3d q{a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2]};
    const Vec3d v = q - p;
    const double r = length(v);
    const Vec3d c{v[1] * d[2] - v[2] * d[1], v[2] * d[0] - v[0] * d[2], v[0] * d[1] - v[1] * d[0]};
    const double sin_theta = length(c) / r;
    const double cos_beta = dot(v, n) / r;
    return cos_beta > 0 ? sin_theta * cos_beta / (r * r) : 0.0;
  };
  const double foot = dot(p - a, d);
  const Vec3d foot_point{a[0] + foot * d[0], a[1] + foot * d[1], a[2] + foot * d[2]};
  const double h = length(p - foot_point);
  std::vector<double> breaks{lo * source_length, hi * source_length};
  for (double k = 0; k < 1e3 * source_length && h > 0; k = (k == 0 ? h / 8 : k * 4))
    for (double s : {foot - k, foot + k})
      if (s > breaks[0] && s < breaks[1]) breaks.push_back(s);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, breaks[i],
                                                                         breaks[i + 1], 10, 1e-12);
  return intensity * sum;
}

// The paper's e(u) of eq. (7): 0.5 (alpha + sin(alpha) cos(alpha)) with u = tan(alpha).
double paper_e(double u) {
  return 0.5 * (std::atan(u) + u / (1 + u * u));
}

// A seeded generator with its own mapping to [lo, hi), so the configurations do not depend
// on the standard library's distributions.
struct Random {
  std::mt19937_64 engine;
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(engine() >> 11) * 0x1.0p-53;
  }
  Vec3d point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Vec3d direction() {
    for (;;) {
      const Vec3d v = point(-1, 1);
      const double l = length(v);
      if (l > 0.1 && l <= 1) return normalized(v);
    }
  }
};

struct Configuration {
  Vec3d p, n, a, b;
};

void check_agreement(const Configuration& c, double tolerance) {
  const double intensity = 150;
  const double closed = linear_illuminance(c.p, c.n, c.a, c.b, intensity);
  const double numeric = linear_illuminance_quadrature(c.p, c.n, c.a, c.b, intensity);
  const double reference = reference_illuminance(c.p, c.n, c.a, c.b, intensity);
  BOOST_TEST_CONTEXT("P=" << c.p[0] << "," << c.p[1] << "," << c.p[2] << " N=" << c.n[0] << ","
                          << c.n[1] << "," << c.n[2] << " A=" << c.a[0] << "," << c.a[1] << ","
                          << c.a[2] << " B=" << c.b[0] << "," << c.b[1] << "," << c.b[2]) {
    BOOST_TEST(relative_difference(closed, reference) <= tolerance,
               "closed " << closed << " reference " << reference);
    BOOST_TEST(relative_difference(numeric, reference) <= tolerance,
               "quadrature " << numeric << " reference " << reference);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linear_source)

// Case A (source parallel to the face). Derivation: with phi_i the signed angle between PQ_t
// and PQ_i (Q_t the foot of the perpendicular, r_t = |PQ_t|), t = r_t tan(phi), sin(theta)
// = cos(phi), and the normal illuminance (on the plane perpendicular to PQ_t) is
//     E_n = (I / r_t) * integral cos^2(phi) dphi = (I / (2 r_t)) [phi + sin(phi) cos(phi)],
// so E = E_n cos(delta) = I [e(u_2) - e(u_1)] F(S_f, Q_1) / r_t^2 with u_i = tan(phi_i) =
// F(S_t, Q_i) / r_t and e(u) = (atan(u) + u / (1 + u^2)) / 2: the printed eq. (7) once its
// subscripts are read as S_t, r_t and F(S_f, .) (the scan prints S_l, r_l).
BOOST_AUTO_TEST_CASE(case_a_parallel_source_matches_the_corrected_eq_7) {
  const Vec3d n{0, 0, 1};
  const double intensity = 200;
  for (const Vec3d& p : {Vec3d{0.3, 0.4, 0}, Vec3d{-2, 0.1, 0}, Vec3d{4, 3, 0}}) {
    const Vec3d q1{-1, 1.5, 2.2}, q2{2.5, 1.5, 2.2};  // along +x at height 2.2
    const Vec3d tau{1, 0, 0};
    const Vec3d foot{p[0], 1.5, 2.2};
    const double r_t = length(foot - p);
    const double u1 = dot(q1 - p, tau) / r_t;  // F(S_t, Q_1) / r_t, signed
    const double u2 = dot(q2 - p, tau) / r_t;
    const double f = dot(q1 - p, n);  // F(S_f, Q_1)
    const double expected = intensity * std::abs(paper_e(u1) - paper_e(u2)) * f / (r_t * r_t);
    // Eq. (6) in angles, with signed angles (the paper's "change the sign of alpha_1" rule).
    const double alpha1 = std::atan(u1), alpha2 = std::atan(u2);
    const double eq6 = 0.5 * intensity / r_t *
                       std::abs(alpha1 + std::sin(alpha1) * std::cos(alpha1) -
                                (alpha2 + std::sin(alpha2) * std::cos(alpha2))) *
                       (f / r_t);
    BOOST_TEST(relative_difference(eq6, expected) <= 1e-14);
    BOOST_TEST(relative_difference(linear_illuminance(p, n, q1, q2, intensity), expected) <= 1e-13);
    BOOST_TEST(relative_difference(reference_illuminance(p, n, q1, q2, intensity), expected) <=
               1e-12);
    BOOST_TEST(relative_difference(linear_illuminance_quadrature(p, n, q1, q2, intensity),
                                   expected) <= 1e-11);
  }
}

// The printed small-u approximation e(u) = u(1 - 2/3 u^2 + 3/5 u^4 - 7/4 u^6) is misprinted:
// atan(u) = u - u^3/3 + u^5/5 - u^7/7 and u/(1+u^2) = u - u^3 + u^5 - u^7, so half their sum
// is u - (2/3) u^3 + (3/5) u^5 - (4/7) u^7 + (5/9) u^9: the last coefficient is 4/7.
BOOST_AUTO_TEST_CASE(case_a_series_has_coefficient_four_sevenths_not_seven_fourths) {
  for (double u : {0.01, 0.02, 0.05}) {
    const double u2 = u * u;
    const double seventh_order =
        (paper_e(u) - u * (1 - 2.0 / 3 * u2 + 3.0 / 5 * u2 * u2)) / (u2 * u2 * u2 * u);
    BOOST_TEST(std::abs(seventh_order - (-4.0 / 7)) <= 0.6 * u2 + 1e-4);
    BOOST_TEST(std::abs(seventh_order - (-7.0 / 4)) > 1.0);
  }
  // With 4/7 the paper's "error below 1 percent for |u| < 0.44" holds (it is ~0.05%).
  for (double u = -0.44; u <= 0.44; u += 0.01) {
    if (u == 0) continue;
    const double u2 = u * u;
    const double series = u * (1 - 2.0 / 3 * u2 + 3.0 / 5 * u2 * u2 - 4.0 / 7 * u2 * u2 * u2);
    BOOST_TEST(std::abs(series - paper_e(u)) <= 1e-3 * std::abs(paper_e(u)));
  }
}

// Case B (source perpendicular to the face): theta = beta, sin(theta) = r_t / r and dl =
// sec(theta) dr, so E = I * integral r_t / r^3 dr = (I r_t / 2) |r_1^-2 - r_2^-2|: eq. (8),
// printed correctly.
BOOST_AUTO_TEST_CASE(case_b_perpendicular_source_matches_eq_8) {
  const double intensity = 120;
  struct Case {
    Vec3d p, n, q1, q2;
  };
  const Case cases[] = {
      {{0.2, 1.7, 0}, {0, 0, 1}, {1, 2, 0.5}, {1, 2, 2.5}},   // vertical tube over a floor
      {{0.2, 1.7, 0}, {0, 0, 1}, {1, 2, 2.5}, {1, 2, 0.5}},   // the same tube reversed
      {{0, 1.5, 0.4}, {1, 0, 0}, {0.5, 1, 1}, {3, 1, 1}},     // tube perpendicular to a wall
      {{5, 5, 5}, {0, -1, 0}, {5.1, 4.9, 5}, {5.1, -20, 5}},  // long tube, P close to it
  };
  for (const Case& c : cases) {
    const double r1 = length(c.q1 - c.p);
    const double r2 = length(c.q2 - c.p);
    const double height1 = dot(c.q1 - c.p, c.n);
    const double r_t = std::sqrt(r1 * r1 - height1 * height1);
    const double expected = 0.5 * intensity * std::abs(1 / (r1 * r1) - 1 / (r2 * r2)) * r_t;
    BOOST_TEST(relative_difference(linear_illuminance(c.p, c.n, c.q1, c.q2, intensity), expected) <=
               1e-13);
    BOOST_TEST(relative_difference(reference_illuminance(c.p, c.n, c.q1, c.q2, intensity),
                                   expected) <= 1e-12);
  }
}

// A vertical tube piercing the floor at horizontal distance r_t = 1 from P: only the part
// above the floor lights P, and by eq. (8) with r_1 = r_t (the crossing point) and r_2^2 =
// 1 + 2^2, E = (I / 2)(1 - 1/5) = 0.4 I.
BOOST_AUTO_TEST_CASE(tube_crossing_the_receiving_plane_counts_only_the_outer_part) {
  const double intensity = 100;
  const Vec3d p{0, 0, 0}, n{0, 0, 1}, a{1, 0, -1}, b{1, 0, 2};
  BOOST_TEST(relative_difference(linear_illuminance(p, n, a, b, intensity), 0.4 * intensity) <=
             1e-14);
  BOOST_TEST(relative_difference(linear_illuminance_quadrature(p, n, a, b, intensity),
                                 0.4 * intensity) <= 1e-11);
  const auto outer = outer_side_interval(p, n, a, b);
  BOOST_TEST_REQUIRE(outer.has_value());
  BOOST_TEST(outer->first == 1.0 / 3, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(outer->second == 1.0);
  // Oblique piercing tube: closed form, library quadrature and reference agree.
  check_agreement({p, n, {1, -1, -1}, {1, 2, 3}}, 1e-10);
  check_agreement({p, normalized({0.3, -0.2, 1}), {-0.5, 0.7, 2}, {1.5, -0.4, -1}}, 1e-10);
}

BOOST_AUTO_TEST_CASE(outer_side_interval_clips_at_the_plane) {
  const Vec3d p{0, 0, 0}, n{0, 0, 1};
  const auto whole = outer_side_interval(p, n, {0, 0, 1}, {3, 0, 2});
  BOOST_TEST_REQUIRE(whole.has_value());
  BOOST_TEST((whole->first == 0.0 && whole->second == 1.0));
  BOOST_TEST(!outer_side_interval(p, n, {0, 0, -1}, {3, 0, -2}).has_value());
  BOOST_TEST(!outer_side_interval(p, n, {0, 0, 0}, {3, 0, 0}).has_value());  // in the plane
  const auto lower = outer_side_interval(p, n, {0, 0, 3}, {0, 1, -1});       // crosses at 3/4
  BOOST_TEST_REQUIRE(lower.has_value());
  BOOST_TEST((lower->first == 0.0 && lower->second == 0.75));
  const auto touching = outer_side_interval(p, n, {0, 0, 0}, {1, 0, 1});  // A on the plane
  BOOST_TEST_REQUIRE(touching.has_value());
  BOOST_TEST((touching->first == 0.0 && touching->second == 1.0));
}

BOOST_AUTO_TEST_CASE(degenerate_sources_give_zero) {
  const Vec3d p{0, 0, 0}, n{0, 0, 1};
  BOOST_TEST(linear_illuminance(p, n, {1, 1, 1}, {1, 1, 1}, 100) == 0.0);     // A == B
  BOOST_TEST(linear_illuminance(p, n, {0, 0, 1}, {0, 0, 3}, 100) == 0.0);     // P on the line
  BOOST_TEST(linear_illuminance(p, n, {0, 0, -1}, {0, 0, 3}, 100) == 0.0);    // P on the tube
  BOOST_TEST(linear_illuminance(p, n, {-1, 0, 0}, {1, 0, 0}, 100) == 0.0);    // in the plane
  BOOST_TEST(linear_illuminance(p, n, {-1, 2, 0}, {1, 5, 0}, 100) == 0.0);    // grazing
  BOOST_TEST(linear_illuminance(p, n, {-1, 2, -1}, {1, 5, -3}, 100) == 0.0);  // behind
  BOOST_TEST(linear_illuminance(p, n, {-1, 2, 1}, {1, 5, 3}, 100, {{0.4, 0.4}}) == 0.0);
  BOOST_TEST(linear_illuminance(p, n, {-1, 2, 1}, {1, 5, 3}, 100, {}) == 0.0);
  BOOST_TEST(linear_illuminance_quadrature(p, n, {0, 0, 1}, {0, 0, 3}, 100) == 0.0);
}

BOOST_AUTO_TEST_CASE(visible_intervals_add_up_and_are_checked) {
  const Vec3d p{0.3, -0.2, 0}, n{0, 0, 1}, a{-1, 0.5, 1.5}, b{2, 1.5, 3};
  const double whole = linear_illuminance(p, n, a, b, 100);
  const double parts = linear_illuminance(p, n, a, b, 100, {{0, 0.2}, {0.2, 0.55}, {0.55, 1}});
  BOOST_TEST(relative_difference(parts, whole) <= 1e-14);
  // Two visible pieces with a blocked gap between them, against the reference.
  const double visible = linear_illuminance(p, n, a, b, 100, {{0.05, 0.3}, {0.62, 0.9}});
  const double expected = reference_illuminance(p, n, a, b, 100, 0.05, 0.3) +
                          reference_illuminance(p, n, a, b, 100, 0.62, 0.9);
  BOOST_TEST(relative_difference(visible, expected) <= 1e-12);
  BOOST_TEST(relative_difference(
                 linear_illuminance_quadrature(p, n, a, b, 100, {{0.05, 0.3}, {0.62, 0.9}}),
                 expected) <= 1e-11);
  // Visible intervals beyond the receiving plane are still clipped by it.
  const Vec3d below{2, 1.5, -1};
  const double clipped = linear_illuminance(p, n, a, below, 100, {{0.0, 1.0}});
  BOOST_TEST(relative_difference(clipped, reference_illuminance(p, n, a, below, 100)) <= 1e-12);
  BOOST_CHECK_THROW(linear_illuminance(p, n, a, b, 100, {{0.5, 0.4}}), std::invalid_argument);
  BOOST_CHECK_THROW(linear_illuminance(p, n, a, b, 100, {{-0.1, 0.4}}), std::invalid_argument);
  BOOST_CHECK_THROW(linear_illuminance(p, n, a, b, 100, {{0.1, 1.5}}), std::invalid_argument);
}

// Random oblique configurations (Case C and everything else): points in a 4 m cube, normals
// uniform on the sphere, tube ends in a 6 m cube, so most tubes are oblique and about half
// cross the receiving plane. The seed is fixed (the paper's year) so that a failure
// reproduces exactly; the generator's own mapping to doubles keeps it portable.
BOOST_AUTO_TEST_CASE(random_configurations_agree_with_quadrature) {
  Random random{std::mt19937_64{1985}};
  for (int i = 0; i < 2000; ++i) {
    const Configuration c{random.point(-2, 2), random.direction(), random.point(-3, 3),
                          random.point(-3, 3)};
    check_agreement(c, 1e-9);
  }
}

// Configurations near the places where a naive evaluation of the closed form loses digits.
BOOST_AUTO_TEST_CASE(near_degenerate_configurations_agree_with_quadrature) {
  const Vec3d n = normalized({0.2, -0.3, 1});
  const std::vector<Configuration> cases{
      // P within 1e-6 m of the tube, foot inside it (E ~ 1/h).
      {{0.5, 1e-6, 0.2}, normalized({0, 1, 0.2}), {-1, 0, 0.2}, {2, 0, 0.2}},
      // P on the line's extension within 1e-9 m: angles near pi/2 at both ends.
      {{3, 1e-9, 1e-9}, normalized({-1, 0.3, 0.4}), {-1, 0, 0}, {2, 0, 0}},
      // P within 1e-9 m and 1e-12 m of the tube, tilted normal.
      {{0.3, 0, -1e-9}, {0, 0.6, 0.8}, {0, 0, 0}, {1, 0, 0}},
      {{0.3, 0, -1e-12}, {0, 0.6, 0.8}, {0, 0, 0}, {1, 0, 0}},
      // P 1e-4 m off the extension, oblique normal.
      {{-2, 1e-4, 0}, n, {-1, 0, 0.3}, {2, 0, 0.6}},
      // Nearly parallel (tilt 1e-10) and nearly perpendicular tubes over a tilted face.
      {{0, 0, 0}, {0, 0, 1}, {-1, 0.4, 1}, {2, 0.4, 1 + 1e-10}},
      {{0, 0, 0}, {0, 0, 1}, {0.5, 0.4, 1}, {0.5 + 1e-10, 0.4, 3}},
      // A 1 micrometre tube 5 m away.
      {{0, 0, 0}, n, {3, 4, 0.1}, {3 + 1e-6, 4, 0.1 + 0.5e-6}},
      // P 1e-7 m from the end A, beside the tube.
      {{1e-7, 0, 0}, normalized({1, 0, 0.1}), {0, 0, 0}, {0, 0, 2}},
      // Foot exactly at the regime switch t0 t1 = h^2 (t0 = 1, t1 = 4, h = 2).
      {{0, 0, 0}, n, {1, 2, 0}, {4, 2, 0}},
      // Tube crossing the plane very close to one end.
      {{0, 0, 0}, {0, 0, 1}, {1, 1, -1e-7}, {2, 1, 1}},
      // Tube just above a face it nearly lies in, long and far.
      {{0, 0, 0}, {0, 0, 1}, {-50, 3, 0.01}, {50, 3, 0.01}},
  };
  for (const Configuration& c : cases) check_agreement(c, 1e-9);
}

// A second evaluation of the derived closed form, in 50-digit arithmetic and in its plain
// angle form E = I / (2h) [c (phi + sin(phi) cos(phi)) - a cos^2(phi)], phi = atan(t / h)
// (docs/illuminance.md), which loses digits in double precision when h << |t| or the tube
// is short; the library's cancellation-free evaluation must match it to double precision.
BOOST_AUTO_TEST_CASE(closed_form_matches_a_fifty_digit_angle_form) {
  using Real = boost::multiprecision::cpp_bin_float_50;
  auto fifty_digits = [](const Vec3d& p, const Vec3d& n, const Vec3d& a, const Vec3d& b) {
    Real d[3], from_a[3], length_squared = 0, t_a = 0, h_squared = 0, axial = 0, lateral = 0;
    for (int i = 0; i < 3; ++i) {
      d[i] = Real(b[i]) - Real(a[i]);
      from_a[i] = Real(a[i]) - Real(p[i]);
      length_squared += d[i] * d[i];
    }
    const Real tube = sqrt(length_squared);
    for (int i = 0; i < 3; ++i) d[i] /= tube;
    for (int i = 0; i < 3; ++i) t_a += from_a[i] * d[i];
    for (int i = 0; i < 3; ++i) {
      const Real w = from_a[i] - t_a * d[i];
      h_squared += w * w;
      axial += Real(n[i]) * d[i];
      lateral += Real(n[i]) * w;
    }
    const Real h = sqrt(h_squared);
    lateral /= h;
    auto primitive = [&](const Real& t) {
      const Real phi = atan2(t, h);
      return Real(lateral * (phi + sin(phi) * cos(phi)) - axial * cos(phi) * cos(phi));
    };
    return static_cast<double>((primitive(t_a + tube) - primitive(t_a)) / (2 * h));
  };
  const std::vector<Configuration> cases{
      {{-1, 0, -1e-3}, {0, 0.6, 0.8}, {0, 0, 0}, {1, 0, 0}},            // beyond the end, h = 1e-3
      {{-1, 0, -1e-9}, {0, 0.6, 0.8}, {0, 0, 0}, {1, 0, 0}},            // beyond the end, h = 1e-9
      {{0.3, 0, -1e-11}, {0, 0.6, 0.8}, {0, 0, 0}, {1, 0, 0}},          // beside the tube
      {{0, 0, 0}, {0, 0, 1}, {3, 4, 1}, {3 + 1e-8, 4, 1 + 1e-8}},       // a 14 nm tube 5 m away
      {{0, 0, 0}, normalized({0.2, 0.1, 1}), {-2, 1, 1}, {4, 1.5, 3}},  // ordinary oblique
  };
  for (const Configuration& c : cases) {
    const double expected = fifty_digits(c.p, c.n, c.a, c.b);
    BOOST_TEST(relative_difference(linear_illuminance(c.p, c.n, c.a, c.b, 1), expected) <= 1e-14);
  }
}

// Flux: element dl sends I sin(theta) dl toward theta, so it emits
//     integral I sin(theta) dOmega = I * integral_0^pi sin(theta) 2 pi sin(theta) dtheta
//                                  = 2 pi I (pi / 2) = pi^2 I per metre,
// and a tube of length L emits pi^2 I L, all of it onto the inner faces of a box around it.
BOOST_AUTO_TEST_CASE(flux_into_a_closed_box_equals_pi_squared_i_l) {
  const Vec3d a{0.6, 0.5, 0.8}, b{2.3, 1.4, 2.0};
  const double intensity = 150;
  const double flux = penumbra::test::flux_into_box(
      [&](const Vec3d& p, const Vec3d& n) { return linear_illuminance(p, n, a, b, intensity); },
      {0, 0, 0}, {3, 2, 2.5}, 8, 8);
  BOOST_TEST(relative_difference(flux, pi * pi * intensity * length(b - a)) <= 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
