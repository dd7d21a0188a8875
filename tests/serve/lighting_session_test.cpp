// LightingSession: the designer's edits (Dobashi 1995 section 4) and relighting by eq. (18).

#include "penumbra/serve/lighting_session.h"

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cmath>
#include <random>

#include "penumbra/base/input_error.h"
#include "penumbra/base/numbers.h"
#include "serve_room.h"

using penumbra::pi;

namespace penumbra::serve {
namespace {

// P_0(x) .. P_n(x) by Bonnet's recurrence, written here independently of the library.
std::vector<double> legendre(int n, double x) {
  std::vector<double> p{1, x};
  for (int l = 1; l < n; ++l) p.push_back(((2 * l + 1) * x * p[l] - l * p[l - 1]) / (l + 1));
  p.resize(n + 1);
  return p;
}

// eq. (19), the trapezoid weights of control intensities at k pi / M, from scratch.
std::vector<double> trapezoid_weights(const std::vector<double>& controls, int degree) {
  const int intervals = static_cast<int>(controls.size()) - 1;
  const double step = pi / intervals;
  std::vector<double> weights(degree + 1, 0.0);
  for (int k = 0; k <= intervals; ++k) {
    const double gamma = k * step, t = (k == 0 || k == intervals) ? 0.5 : 1.0;
    const std::vector<double> p = legendre(degree, std::cos(gamma));
    for (int l = 0; l <= degree; ++l)
      weights[l] += (2 * l + 1) / 2.0 * t * controls[k] * p[l] * std::sin(gamma) * step;
  }
  return weights;
}

LightingSession room_session() {
  return LightingSession(test::serve_room_basis(), test::serve_room_scene());
}

double norm(const Vec3d& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(lighting_session)

BOOST_AUTO_TEST_CASE(control_points_sample_the_lamp_every_10_degrees) {
  const LightingSession session = room_session();
  const LampState& lamp = session.lamp("downlight");
  BOOST_REQUIRE(lamp.editor);
  const auto& controls = lamp.editor->control_intensities();
  BOOST_REQUIRE_EQUAL(controls.size(), 19u);
  // the fixture's lid: 600 cos^2(gamma) within 90 degrees, dark beyond
  for (int k = 0; k <= 18; ++k) {
    const double gamma = k * pi / 18;
    const double expected = k <= 9 ? 600 * std::cos(gamma) * std::cos(gamma) : 0.0;
    BOOST_TEST(controls[k] == expected, boost::test_tools::tolerance(1e-9) << "k = " << k);
  }
  BOOST_TEST(!session.lamp("spot").editor->weights().empty());
}

BOOST_AUTO_TEST_CASE(moving_a_control_point_changes_the_weights_by_eq_21) {
  LightingSession session = room_session();
  const int k = 3;
  const std::vector<double> before = session.lamp("downlight").editor->weights();
  const double old_intensity = session.lamp("downlight").editor->control_intensities()[k];
  session.move_control_point("downlight", k, 100);
  const std::vector<double> after = session.lamp("downlight").editor->weights();
  const double gamma = k * pi / 18;
  const std::vector<double> p = legendre(test::serve_room_degree, std::cos(gamma));
  for (int l = 0; l <= test::serve_room_degree; ++l) {
    const double increment =
        (2 * l + 1) / 2.0 * (100 - old_intensity) * p[l] * std::sin(gamma) * pi / 18;
    BOOST_TEST(after[l] == before[l] + increment, boost::test_tools::tolerance(1e-9));
  }
  // and equal to eq. (19) over the moved curve from scratch
  const std::vector<double> scratch = trapezoid_weights(
      session.lamp("downlight").editor->control_intensities(), test::serve_room_degree);
  for (int l = 0; l <= test::serve_room_degree; ++l)
    BOOST_TEST(after[l] == scratch[l], boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(bad_edits_are_refused) {
  LightingSession session = room_session();
  BOOST_CHECK_THROW(session.move_control_point("nope", 0, 1), UnknownLight);
  BOOST_CHECK_THROW(session.move_control_point("downlight", 19, 1), std::invalid_argument);
  BOOST_CHECK_THROW(session.move_control_point("downlight", 0, -1), std::invalid_argument);
  BOOST_CHECK_THROW(session.move_control_point("downlight", 0, NAN), std::invalid_argument);
  BOOST_CHECK_THROW(session.update("downlight", {{"colour", {1, 2}}}), std::invalid_argument);
  BOOST_CHECK_THROW(session.update("downlight", {{"scale", -1}}), std::invalid_argument);
  BOOST_CHECK_THROW(session.update("downlight", {{"aim", {2, 1.5, 2.7}}}), std::invalid_argument);
  BOOST_CHECK_THROW(session.update("downlight", {{"brightness", 1}}), std::invalid_argument);
  // nothing changed: a failed update is all or nothing
  BOOST_CHECK_THROW(session.update("downlight", {{"scale", 0.5}, {"colour", "red"}}),
                    std::invalid_argument);
  BOOST_TEST(session.lamp("downlight").scale == 1.0);
}

BOOST_AUTO_TEST_CASE(aiming_at_a_point_turns_the_axis_toward_it) {
  LightingSession session = room_session();
  session.update("spot", {{"aim", {1.0, 1.0, 0.0}}});
  const LampState& spot = session.lamp("spot");
  const Vec3d toward{1.0 - 3.5, 1.0 - 0.5, 0.0 - 2.6};
  for (int i = 0; i < 3; ++i)
    BOOST_TEST(spot.axis[i] == toward[i] / norm(toward), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(spot.c0[0] * spot.axis[0] + spot.c0[1] * spot.axis[1] +
                      spot.c0[2] * spot.axis[2]) < 1e-12);
}

// Direct illuminance below the downlight alone, relit from the basis (eq. 18), against
// the inverse-square law with the series the lamp is lit with: E = I(gamma) cos(a) / r^2.
BOOST_AUTO_TEST_CASE(relit_direct_illuminance_follows_the_lit_series) {
  LightingSession session = room_session();
  session.update("spot", {{"scale", 0}});
  session.move_control_point("downlight", 2, 150);
  for (bool sigma : {true, false}) {
    session.update("downlight", {{"sigma", sigma}});
    const auto lux = session.lux_at({2.6, 1.0, 0.0});
    BOOST_REQUIRE(lux);
    const basis::Patch& patch = session.basis().mesh.patches()[lux->patch];
    const Vec3d lamp{2.0, 1.5, 2.7};
    const Vec3d d{patch.centre[0] - lamp[0], patch.centre[1] - lamp[1], patch.centre[2] - lamp[2]};
    const double r = norm(d), gamma = std::acos(-d[2] / r), cos_incidence = -d[2] / r;
    const std::vector<double> weights = session.lamp("downlight").lighting_weights();
    const std::vector<double> p = legendre(test::serve_room_degree, std::cos(gamma));
    double intensity = 0;
    for (int l = 0; l <= test::serve_room_degree; ++l) intensity += weights[l] * p[l];
    BOOST_TEST(lux->direct[0] == intensity * cos_incidence / (r * r),
               boost::test_tools::tolerance(1e-4) << "sigma " << sigma);
  }
}

BOOST_AUTO_TEST_CASE(dimming_and_colour_scale_the_relit_values) {
  LightingSession session = room_session();
  const Eigen::VectorXf full = session.patch_illuminance().lux;
  session.update("downlight", {{"scale", 0.5}});
  session.update("spot", {{"scale", 0.5}});
  const Eigen::VectorXf half = session.patch_illuminance().lux;
  BOOST_TEST((half - 0.5f * full).cwiseAbs().maxCoeff() <= 1e-5f * full.maxCoeff());
  // a red downlight alone leaves green and blue dark
  session.update("downlight", {{"colour", {1, 0, 0}}});
  session.update("spot", {{"scale", 0}});
  const PatchIlluminance& red = session.patch_illuminance();
  BOOST_TEST(red.total.col(0).maxCoeff() > 0.0f);
  BOOST_TEST(red.total.col(1).cwiseAbs().maxCoeff() == 0.0f);
  BOOST_TEST(session.relit().vertex_luminance.col(2).cwiseAbs().maxCoeff() == 0.0f);
}

// The vertex illuminance pi L / rho (relight_scene) against its definition, the
// area-weighted mean of the patches' illuminance around the vertex.
BOOST_AUTO_TEST_CASE(vertex_lux_is_the_mean_of_the_patches_lux) {
  LightingSession session = room_session();
  session.update("spot", {{"colour", {1, 0.5, 0.2}}});
  const Eigen::VectorXf& lux = session.relit().vertex_lux;
  const Eigen::MatrixXf patch_lux = session.patch_illuminance().lux;
  const Eigen::MatrixXf mean = session.basis().mesh.vertex_average(patch_lux);
  BOOST_REQUIRE_EQUAL(lux.size(), mean.rows());
  BOOST_TEST((lux - mean.col(0)).cwiseAbs().maxCoeff() <= 1e-4f * mean.maxCoeff());
}

BOOST_AUTO_TEST_CASE(a_lighting_file_round_trips) {
  LightingSession edited = room_session();
  edited.move_control_point("downlight", 4, 321);
  edited.update("downlight", {{"sigma", false}, {"colour", {1, 0.8, 0.6}}, {"scale", 0.7}});
  edited.update("spot", {{"aim", {1, 2, 0}}});
  const nlohmann::json file = nlohmann::json::parse(edited.lighting_json().dump());
  LightingSession loaded = room_session();
  loaded.load_lighting_json(file);
  const basis::Lighting a = edited.lighting(), b = loaded.lighting();
  BOOST_REQUIRE_EQUAL(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    BOOST_TEST((a[i].coefficients - b[i].coefficients).cwiseAbs().maxCoeff() < 1e-9);
    BOOST_TEST(a[i].colour == b[i].colour);
    BOOST_TEST(a[i].scale == b[i].scale);
  }
}

BOOST_AUTO_TEST_CASE(a_bad_lighting_file_changes_nothing) {
  LightingSession session = room_session();
  const nlohmann::json before = session.lighting_json();
  nlohmann::json file = before;
  file["lights"][0]["scale"] = 0.1;
  file["lights"].push_back({{"name", "nope"}});
  BOOST_CHECK_THROW(session.load_lighting_json(file), UnknownLight);
  BOOST_CHECK_THROW(session.load_lighting_json({{"lights", nlohmann::json::array()}}),
                    std::invalid_argument);
  nlohmann::json short_curve = before;
  short_curve["lights"][0]["controls"] = {1, 2, 3};
  BOOST_CHECK_THROW(session.load_lighting_json(short_curve), std::invalid_argument);
  BOOST_TEST(session.lighting_json() == before);
}

BOOST_AUTO_TEST_CASE(a_basis_of_another_scene_is_refused) {
  Scene other = test::serve_room_scene();
  other.lights[1].name = "renamed";
  BOOST_CHECK_THROW(LightingSession(test::serve_room_basis(), other), InputError);
  other.lights.pop_back();
  BOOST_CHECK_THROW(LightingSession(test::serve_room_basis(), other), InputError);
}

// Issue #10's target: relighting after an edit within 50 ms for 16,000 patches at degree
// 8. A synthetic basis of that size (values random: only the arithmetic is timed; seed
// fixed so the run is repeatable), two point lamps, colour (three channels).
BOOST_AUTO_TEST_CASE(relighting_16000_patches_at_degree_8_takes_milliseconds) {
  const int nu = 160, nv = 100, degree = 8, columns = (degree + 1) * (degree + 1);
  std::vector<Vec3d> vertices;
  for (int b = 0; b <= nv; ++b)
    for (int a = 0; a <= nu; ++a) vertices.push_back({a * 0.05, b * 0.05, 0.0});
  std::vector<basis::Patch> patches;
  for (int b = 0; b < nv; ++b)
    for (int a = 0; a < nu; ++a) {
      basis::Patch patch;
      patch.centre = {(a + 0.5) * 0.05, (b + 0.5) * 0.05, 0.0};
      patch.normal = {0, 0, 1};
      patch.area = 0.0025;
      patch.reflectance = {0.5, 0.5, 0.5};
      const auto corner = static_cast<std::uint32_t>(b * (nu + 1) + a);
      patch.vertices = {corner, corner + 1, corner + nu + 2, corner + nu + 1};
      patches.push_back(patch);
    }
  basis::BasisLuminances basis;
  basis.mesh = basis::PatchMesh(vertices, patches);
  basis.channels = 3;
  std::mt19937 random(20261122);  // any fixed seed: the values do not matter, the sizes do
  std::uniform_real_distribution<float> value(0, 1);
  const auto block = [&](Eigen::Index rows) {
    Eigen::MatrixXf values(rows, columns);
    for (Eigen::Index i = 0; i < values.size(); ++i) values.data()[i] = value(random);
    return basis::BasisBlock(values);
  };
  const auto n = static_cast<Eigen::Index>(patches.size());
  const auto v = static_cast<Eigen::Index>(vertices.size());
  basis::Lighting lighting;
  for (int lamp = 0; lamp < 2; ++lamp) {
    basis::BasisLight light;
    light.columns = {"lamp" + std::to_string(lamp), basis::LightKind::point, degree, lamp * columns,
                     columns};
    light.direct = block(n);
    for (int channel = 0; channel < 3; ++channel) {
      light.total.push_back(block(n));
      light.vertex_luminance.push_back(block(v));
    }
    basis.lights.push_back(std::move(light));
    lighting.push_back({Eigen::VectorXd::Constant(columns, 0.1), {1, 1, 1}, 1});
  }
  const Eigen::MatrixX3f reflectance = vertex_reflectance(basis.mesh);
  std::vector<double> times;
  for (int run = 0; run < 7; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const RelitScene relit = relight_scene(basis, lighting, reflectance);
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    BOOST_REQUIRE_EQUAL(relit.vertex_luminance.rows(), v);
  }
  std::sort(times.begin(), times.end());
  BOOST_TEST_MESSAGE("relight of " << n << " patches, " << v
                                   << " vertices, degree 8, 2 lamps: median " << times[3] * 1e3
                                   << " ms");
#ifdef NDEBUG
  BOOST_TEST(times[3] < 0.05);
#endif
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace penumbra::serve
