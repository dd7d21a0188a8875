// Dobashi 1995 section 4.1: trapezoid weights (eq. 19) and their incremental update
// (eq. 21) when a control point moves.

#include "penumbra/basis/legendre_editor.h"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "exact_integrals.h"
#include "penumbra/base/numbers.h"

using penumbra::pi;
using namespace penumbra::basis;
using penumbra::test::moment_of_legendre;

namespace {

double spot(double g) {
  return g < pi / 2 ? 800 * std::pow(std::cos(g), 10) : 0.0;
}

// the exact weights of spot: 800 (2l + 1)/2 int_0^1 x^10 P_l dx (exact_integrals.h).
double exact_spot_weight(int l) {
  return 800 * (2 * l + 1) / 2.0 * moment_of_legendre(10, l);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(legendre_editor)

BOOST_AUTO_TEST_CASE(trapezoid_weights_converge_to_the_exact_weights_at_second_order) {
  // The kink at 90 degrees is a node for every even M, so the trapezoid error is
  // O(dgamma^2): doubling M divides it by about 4.
  const int degree = 8;
  std::vector<double> errors;
  for (int intervals : {90, 180, 360, 720, 1440}) {
    const LegendreWeightEditor editor = LegendreWeightEditor::sampled(spot, degree, intervals);
    double worst = 0;
    for (int l = 0; l <= degree; ++l)
      worst = std::max(worst, std::abs(editor.weights()[l] - exact_spot_weight(l)));
    errors.push_back(worst);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    BOOST_TEST(ratio > 3.6);
    BOOST_TEST(ratio < 4.4);
  }
  // At 1/8 degree spacing the weights are within 5e-3 cd of the exact ones, 1.4e-4 of
  // w_0 = 800 / 22 cd.
  BOOST_TEST(errors.back() < 5e-3);
}

BOOST_AUTO_TEST_CASE(incremental_update_equals_a_full_recomputation) {
  const int degree = 8, intervals = 36;
  LegendreWeightEditor editor = LegendreWeightEditor::sampled(spot, degree, intervals);
  // Fixed seed: a reproducible sequence of edits, ends included.
  std::mt19937 random(9);
  std::uniform_int_distribution<int> point(0, intervals);
  std::uniform_real_distribution<double> candela(0, 1000);
  for (int edit = 0; edit < 200; ++edit) editor.move_control_point(point(random), candela(random));
  editor.move_control_point(0, 1234);
  editor.move_control_point(intervals, 55);
  const LegendreWeightEditor fresh(degree, editor.control_intensities());
  for (int l = 0; l <= degree; ++l) {
    BOOST_TEST(std::abs(editor.weights()[l] - fresh.weights()[l]) <= 1e-11, "l " << l);
    BOOST_TEST(std::abs(editor.weights()[l] - editor.recomputed_weights()[l]) <= 1e-11);
  }
}

BOOST_AUTO_TEST_CASE(scanned_eq_21_lacks_the_factor_2l_plus_1_over_2) {
  // Moving one control point by dI changes w_l by (2l + 1)/2 dI f_l(g_k) dgamma
  // (differentiate eq. 19); the scan's eq. (21) omits (2l + 1)/2, which is right for no
  // l > 0 (and wrong by a factor of 2 for l = 0).
  const int degree = 4, intervals = 18, k = 5;
  LegendreWeightEditor editor = LegendreWeightEditor::sampled(spot, degree, intervals);
  const std::vector<double> before = editor.weights();
  const double old_intensity = editor.control_intensities()[k], new_intensity = 300;
  editor.move_control_point(k, new_intensity);
  const double dgamma = pi / intervals, g = k * dgamma;
  for (int l = 0; l <= degree; ++l) {
    const double f = std::legendre(l, std::cos(g)) * std::sin(g);
    const double scanned = before[l] - (old_intensity - new_intensity) * f * dgamma;
    const double derived =
        before[l] + (2 * l + 1) / 2.0 * (new_intensity - old_intensity) * f * dgamma;
    BOOST_TEST(std::abs(editor.weights()[l] - derived) <= 1e-12);
    if (std::abs(f) > 1e-3) BOOST_TEST(std::abs(editor.weights()[l] - scanned) > 1e-3);
  }
}

BOOST_AUTO_TEST_CASE(pole_control_points_carry_no_weight) {
  // f_l(0) = f_l(pi) = 0: the sphere has no area at the poles.
  LegendreWeightEditor editor = LegendreWeightEditor::sampled(spot, 4, 18);
  const std::vector<double> before = editor.weights();
  editor.move_control_point(0, 0);
  editor.move_control_point(18, 5000);
  for (int l = 0; l <= 4; ++l) BOOST_TEST(editor.weights()[l] == before[l]);
}

BOOST_AUTO_TEST_SUITE_END()
