// Relighting from basis luminances (Dobashi 1995 section 3.5, eq. 18) against direct
// radiosity solves of the re-aimed and re-specified scene, the basis file round trip, and
// SVD compression within its stated error.

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <fstream>

#include "penumbra/base/input_error.h"
#include "penumbra/basis/basis_file.h"
#include "penumbra/basis/relight.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/photometry/distribution.h"
#include "radiosity_scenes.h"
#include "support/fixtures.h"

using namespace penumbra;
using namespace penumbra::basis;

namespace {

const char* kLamp =
    R"({"name": "lamp", "point": [2, 2, 3.5], "lid": {"cardioid": true, "candela": 500},
                        "axis": [0, 0, -1]})";

BasisOptions small_options() {
  BasisOptions options;
  options.patch_size = 1;
  options.form_factors.rays = 256;
  options.radiosity.tolerance = 1e-10;
  options.sigma = false;  // plain weights: a polynomial distribution is then represented exactly
  return options;
}

// the relit total (grey channel) against a direct solve of scene: max |difference| over
// max |E|.
double relative_difference(const Relit& relit, const SceneRadiosity& direct) {
  return (relit.total.col(0).cast<double>() - direct.total.col(0)).cwiseAbs().maxCoeff() /
         direct.total.col(0).cwiseAbs().maxCoeff();
}

Vec3d aimed(const Vec3d& from, const Vec3d& at) {
  using namespace vector_ops;
  return normalized(at - from);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(relighting)

BOOST_AUTO_TEST_CASE(default_lighting_reproduces_the_direct_solve) {
  // the cardioid (1 + cos g)/2 is a degree-1 series: degree 2 holds it exactly, so the basis
  // sum equals the solve with the exact distribution up to float storage (1e-7) and the
  // solver's tolerance
  const Scene scene = test::closed_room(4, 0.6, kLamp);
  BasisOptions options = small_options();
  options.degree = 2;
  const BasisLuminances basis = compute_basis(scene, options);
  const SceneRadiosity direct = solve_scene_radiosity(scene, options);
  BOOST_TEST(relative_difference(relight(basis, default_lighting(basis)), direct) < 1e-6);
}

BOOST_AUTO_TEST_CASE(reaimed_lamp_equals_a_solve_with_that_aiming) {
  Scene scene = test::closed_room(4, 0.6, kLamp);
  BasisOptions options = small_options();
  options.degree = 2;
  const BasisLuminances basis = compute_basis(scene, options);
  const Vec3d target{3, 1, 0};
  const Vec3d axis = aimed({2, 2, 3.5}, target);
  Lighting lighting = default_lighting(basis);
  const auto lid = photometry::make_distribution(
      nlohmann::json::parse(R"({"cardioid": true, "candela": 500})"), {"test", "lid", "."});
  lighting[0].coefficients =
      world_coefficients(*lid, 2, axis, reaimed_c0(axis, basis.lights[0].c0), false);
  PointLight& lamp = std::get<PointLight>(scene.lights[0].source);
  lamp.c0 = reaimed_c0(axis, lamp.c0);  // the photometric frame must stay orthonormal
  lamp.axis = axis;
  const SceneRadiosity direct = solve_scene_radiosity(scene, options);
  const Relit relit = relight(basis, lighting);
  BOOST_TEST(relative_difference(relit, direct) < 1e-6);
  // and the re-aiming changed the lighting by far more than that
  BOOST_TEST(relative_difference(relight(basis, default_lighting(basis)), direct) > 0.05);
  // dimming and colour are linear
  lighting[0].scale = 0.5;
  lighting[0].colour = {1, 0.5, 0.25};
  const Relit dimmed = relight(basis, lighting);
  BOOST_TEST((dimmed.total.col(2) - 0.125f * relit.total.col(0)).cwiseAbs().maxCoeff() <
             1e-6 * relit.total.col(0).maxCoeff());
}

BOOST_AUTO_TEST_CASE(real_distribution_converges_with_degree) {
  // a measured, non-polynomial distribution: the relit result approaches the exact solve
  // as the degree grows (the paper: about 20% maximum error at degree 5-8)
  const std::string file = test::photometry_fixture("ies-real/1.IES").string();
  const std::string lamp =
      R"({"name": "lamp", "point": [2, 2, 3.5], "lid": {"ies": ")" + file + R"("}})";
  const Scene scene = test::closed_room(4, 0.5, lamp);
  BasisOptions options = small_options();
  const SceneRadiosity direct = solve_scene_radiosity(scene, options);
  // docs/basis.md reports 32%, 21% and 9% at degrees 2, 5 and 8 (plain weights): each
  // degree must stay within those figures, rounded up to the next percent.
  const std::pair<int, double> bounds[] = {{2, 0.33}, {5, 0.22}, {8, 0.09}};
  double previous = 1e300;
  for (const auto& [degree, bound] : bounds) {
    options.degree = degree;
    const BasisLuminances basis = compute_basis(scene, options);
    const double error = relative_difference(relight(basis, default_lighting(basis)), direct);
    BOOST_TEST_MESSAGE("degree " << degree << ": max relative error " << error);
    BOOST_TEST(error < previous);
    BOOST_TEST(error <= bound, "degree " << degree << ": " << error);
    previous = error;
  }
}

BOOST_AUTO_TEST_CASE(basis_file_round_trip_and_compression) {
  const Scene scene = test::closed_room(4, 0.6, kLamp);
  BasisOptions options = small_options();
  options.degree = 4;
  const BasisLuminances basis = compute_basis(scene, options);
  const auto dir = test::scratch_dir("relight_round_trip");
  write_basis(dir / "b.pbl", basis);
  const BasisLuminances read = read_basis(dir / "b.pbl");
  BOOST_TEST(read.mesh.size() == basis.mesh.size());
  const Relit a = relight(basis, default_lighting(basis)),
              b = relight(read, default_lighting(read));
  BOOST_TEST((a.total - b.total).cwiseAbs().maxCoeff() == 0);
  BOOST_TEST((a.vertex_luminance - b.vertex_luminance).cwiseAbs().maxCoeff() == 0);

  // compressed: each block within its stated Frobenius error, and so is the relit result
  // for the stored coefficients (|(M - M_r) c| <= ||M - M_r||_F |c|)
  options.compression = 0.1;
  const BasisLuminances small = compute_basis(scene, options);
  const BasisBlock& block = small.lights[0].total[0];
  const Eigen::MatrixXf exact = basis.lights[0].total[0].full();
  BOOST_TEST(block.is_compressed());
  BOOST_TEST(block.rank() < exact.cols());
  BOOST_TEST_MESSAGE("rank " << block.rank() << " of " << exact.cols() << ", error "
                             << block.error());
  BOOST_TEST((block.full() - exact).norm() <= 1.01 * 0.1 * exact.norm());
  const Eigen::VectorXf c = basis.lights[0].coefficients.cast<float>();
  const Relit s = relight(small, default_lighting(small));
  BOOST_TEST((s.total.col(0) - a.total.col(0)).norm() <=
             1.01 * 0.1 * exact.norm() * c.norm() + 1e-3);
  write_basis(dir / "small.pbl", small);
  const Relit t = relight(read_basis(dir / "small.pbl"), default_lighting(small));
  BOOST_TEST((s.total - t.total).cwiseAbs().maxCoeff() == 0);
}

BOOST_AUTO_TEST_CASE(damaged_basis_files_are_refused_with_the_file_named) {
  const auto dir = test::scratch_dir("relight_damaged");
  const Scene scene = test::closed_room(4, 0.6, kLamp);
  BasisOptions options = small_options();
  options.degree = 1;
  write_basis(dir / "b.pbl", compute_basis(scene, options));
  std::string bytes = test::read_text(dir / "b.pbl");
  const auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(dir / name, std::ios::binary) << content;
    return dir / name;
  };
  const auto refused = [&](const std::filesystem::path& path, const std::string& fragment) {
    try {
      read_basis(path);
    } catch (const InputError& e) {
      const std::string message = e.what();
      BOOST_TEST_CONTEXT(message) {
        BOOST_TEST(message.find(path.filename().string()) != std::string::npos);
        BOOST_TEST(message.find(fragment) != std::string::npos);
      }
      return;
    }
    BOOST_ERROR("accepted " << path);
  };
  refused(write("truncated.pbl", bytes.substr(0, bytes.size() - 10)), "past the end");
  refused(write("magic.pbl", "PNG" + bytes.substr(3)), "magic");
  refused(write("empty.pbl", ""), "magic");
  refused(dir / "missing.pbl", "cannot open");
  std::string longer = bytes + "x";
  refused(write("longer.pbl", longer), "longer");
}

BOOST_AUTO_TEST_SUITE_END()
