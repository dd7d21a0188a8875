#include <boost/test/unit_test.hpp>

#include <cmath>

#include "penumbra/base/numbers.h"
#include "penumbra/raytrace/optics.h"

namespace {

using penumbra::Vec3d;
using namespace penumbra::raytrace;

double dot(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec3d& a) {
  return std::sqrt(dot(a, a));
}
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

using penumbra::pi;

// An incident unit direction at angle theta from the normal (0, 0, 1), travelling down,
// in the plane spanned by the normal and the tangent (cos(phi), sin(phi), 0).
Vec3d incident(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(optics)

BOOST_AUTO_TEST_CASE(reflection_keeps_the_angle_and_the_plane_of_incidence) {
  const Vec3d normal{0, 0, 1};
  for (double theta : {0.0, 0.1, 0.7, 1.2, 1.5})
    for (double phi : {0.0, 1.0, 2.5}) {
      const Vec3d v = incident(theta, phi);
      const Vec3d r = reflected_direction(v, normal);
      // The law of reflection written out: the tangential part is kept, the normal part
      // changes sign, so R = (sin t cos p, sin t sin p, +cos t).
      BOOST_TEST(std::abs(r[0] - std::sin(theta) * std::cos(phi)) < 1e-14);
      BOOST_TEST(std::abs(r[1] - std::sin(theta) * std::sin(phi)) < 1e-14);
      BOOST_TEST(std::abs(r[2] - std::cos(theta)) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(whitted_vectors_follow_their_definitions) {
  // Section 2 with V not unit: V' = V / |V.N| has V'.N = -1, R = V' + 2N.
  const Vec3d v{3, -1, -2};
  const Vec3d normal{0, 0, 1};
  const WhittedVectors w = whitted_vectors(v, normal, 1.5);
  BOOST_TEST(std::abs(dot(w.scaled_incident, normal) + 1) < 1e-15);
  BOOST_TEST(std::abs(w.reflected[0] - 1.5) < 1e-15);
  BOOST_TEST(std::abs(w.reflected[1] + 0.5) < 1e-15);
  BOOST_TEST(std::abs(w.reflected[2] - 1) < 1e-15);
  // k_f from its definition: |V'|^2 = (9 + 1 + 4) / 4, |V' + N|^2 = (9 + 1) / 4.
  BOOST_TEST(std::abs(w.k_f - 1 / std::sqrt(2.25 * 14 / 4 - 10.0 / 4)) < 1e-15);
  BOOST_REQUIRE(w.refracted.has_value());
}

BOOST_AUTO_TEST_CASE(refraction_obeys_snells_law) {
  const Vec3d normal{0, 0, 1};
  for (double n : {1.33, 1.5, 2.4, 1 / 1.5})
    for (double theta : {0.0, 0.2, 0.5, 0.9, 1.3})
      for (double phi : {0.0, 0.8, 3.0}) {
        const Vec3d v = incident(theta, phi);
        // Snell: sin(theta_i) = k_n sin(theta_t); beyond the critical angle no ray passes.
        const double sin_t = std::sin(theta) / n;
        const auto p = refracted_direction(v, normal, n);
        if (sin_t >= 1) {
          BOOST_TEST(!p.has_value());
          continue;
        }
        BOOST_REQUIRE(p.has_value());
        BOOST_TEST(std::abs(norm(*p) - 1) < 1e-14);
        // Travels on through the surface, at theta_t from -N ...
        const double theta_t = std::asin(sin_t);
        BOOST_TEST(std::abs(-(*p)[2] - std::cos(theta_t)) < 1e-13);
        // ... on the same side of the normal as V's tangential part, in the plane of
        // incidence (P is coplanar with V and N).
        BOOST_TEST(std::abs((*p)[0] - sin_t * std::cos(phi)) < 1e-13);
        BOOST_TEST(std::abs((*p)[1] - sin_t * std::sin(phi)) < 1e-13);
        BOOST_TEST(std::abs(dot(*p, cross(v, normal))) < 1e-13);
      }
}

BOOST_AUTO_TEST_CASE(total_internal_reflection_begins_at_the_critical_angle) {
  // Leaving glass (n = 1.5) for air: k_n = 1 / 1.5, critical angle asin(1 / 1.5).
  const double critical = std::asin(1 / 1.5);
  const Vec3d normal{0, 0, 1};
  BOOST_TEST(refracted_direction(incident(critical - 1e-6, 0.3), normal, 1 / 1.5).has_value());
  BOOST_TEST(!refracted_direction(incident(critical + 1e-6, 0.3), normal, 1 / 1.5).has_value());
  BOOST_TEST(whitted_vectors(incident(critical + 1e-6, 0.3), normal, 1 / 1.5).k_f == 0.0);
  // Just below the critical angle the ray leaves almost grazing.
  const auto grazing = refracted_direction(incident(critical - 1e-9, 0.3), normal, 1 / 1.5);
  BOOST_REQUIRE(grazing.has_value());
  BOOST_TEST(std::abs((*grazing)[2]) < 1e-3);
  // Entering the denser medium there is never total internal reflection.
  BOOST_TEST(refracted_direction(incident(pi / 2 - 1e-9, 0.3), normal, 1.5).has_value());
}

BOOST_AUTO_TEST_CASE(the_sign_convention_faces_the_ray_and_inverts_the_index) {
  const Vec3d outward{0, 1, 0};
  const FacingSurface in = face_the_ray({0, -2, 1}, outward, 1.5);
  BOOST_TEST(in.entering);
  BOOST_TEST(in.relative_index == 1.5);
  BOOST_TEST(in.normal[1] == 1.0);
  const FacingSurface out = face_the_ray({0, 2, 1}, outward, 1.5);
  BOOST_TEST(!out.entering);
  BOOST_TEST(std::abs(out.relative_index - 1 / 1.5) < 1e-16);
  BOOST_TEST(out.normal[1] == -1.0);
}

BOOST_AUTO_TEST_CASE(fresnel_reflectance_matches_the_angle_form_of_fresnels_equations) {
  // An independent form: r_s = -sin(ti - tt) / sin(ti + tt), r_p = tan(ti - tt) / tan(ti + tt)
  // (Born and Wolf 1.5.2), with sin(tt) = sin(ti) / n.
  for (double n : {1.33, 1.5, 2.4})
    for (double theta : {0.05, 0.3, 0.7, 1.0, 1.4}) {
      const double tt = std::asin(std::sin(theta) / n);
      const double rs = -std::sin(theta - tt) / std::sin(theta + tt);
      const double rp = std::tan(theta - tt) / std::tan(theta + tt);
      BOOST_TEST(std::abs(fresnel_reflectance(std::cos(theta), n) - (rs * rs + rp * rp) / 2) <
                 1e-14);
    }
  // Normal incidence: ((n - 1) / (n + 1))^2 = 0.04 for n = 1.5.
  BOOST_TEST(std::abs(fresnel_reflectance(1, 1.5) - 0.04) < 1e-15);
  // Brewster's angle tan(t) = n: the p part vanishes.
  const double brewster = std::atan(1.5);
  const double tt = std::asin(std::sin(brewster) / 1.5);
  const double rs = std::sin(brewster - tt) / std::sin(brewster + tt);
  BOOST_TEST(std::abs(fresnel_reflectance(std::cos(brewster), 1.5) - rs * rs / 2) < 1e-14);
  // Beyond the critical angle from inside: all light is reflected.
  BOOST_TEST(fresnel_reflectance(std::cos(0.8), 1 / 1.5) == 1.0);
}

BOOST_AUTO_TEST_SUITE_END()
