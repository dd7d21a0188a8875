// The inverse problem (relight --fit): non-negative least squares against its optimality
// conditions, and a distribution recovered from the illuminances it produces.

#include <Eigen/QR>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "penumbra/basis/inverse_lighting.h"
#include "penumbra/basis/nonnegative_least_squares.h"
#include "penumbra/basis/scene_radiosity.h"
#include "penumbra/photometry/distribution.h"
#include "radiosity_scenes.h"

using namespace penumbra;
using namespace penumbra::basis;

BOOST_AUTO_TEST_SUITE(inverse_lighting)

BOOST_AUTO_TEST_CASE(nnls_meets_the_karush_kuhn_tucker_conditions) {
  // random problems whose unconstrained optimum has negative entries: the solution must
  // satisfy x >= 0, g = A^T (A x - b) >= 0, and g_j = 0 where x_j > 0
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::MatrixXd A(30, 8);
    Eigen::VectorXd b(30);
    for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = normal(random);
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = normal(random);
    const NnlsResult result = nonnegative_least_squares(A, b);
    BOOST_TEST(result.converged);
    const Eigen::VectorXd g = A.transpose() * (A * result.x - b);
    const double scale = (A.transpose() * b).cwiseAbs().maxCoeff();
    int active = 0;
    for (Eigen::Index j = 0; j < 8; ++j) {
      BOOST_TEST(result.x[j] >= 0);
      if (result.x[j] > 0) {
        BOOST_TEST(std::abs(g[j]) < 1e-9 * scale);
      } else {
        BOOST_TEST(g[j] > -1e-9 * scale);
        ++active;
      }
    }
    const Eigen::VectorXd free = A.colPivHouseholderQr().solve(b);
    if (free.minCoeff() < 0) BOOST_TEST(active > 0);  // the bound was needed
  }
}

BOOST_AUTO_TEST_CASE(fit_recovers_the_illuminances_of_a_known_distribution) {
  // targets = the relit illuminances of a cardioid-like curve given at every 30 degrees;
  // the fit (same control angles) must reproduce every target
  const Scene scene = test::closed_room(
      4, 0.5, R"({"name": "lamp", "point": [2, 2, 3.5], "candela": 100, "axis": [0, 0, -1]})");
  BasisOptions options;
  options.patch_size = 1;
  options.degree = 4;
  options.form_factors.rays = 256;
  const BasisLuminances basis = compute_basis(scene, options);
  const std::vector<double> angles = {0, 30, 60, 90, 120, 150, 180};
  const std::vector<double> candela = {800, 760, 600, 400, 200, 60, 0};
  nlohmann::json spec = {{"table_deg", angles}, {"candela", candela}};
  const auto lid = photometry::make_distribution(spec, {"test", "lid", "."});
  Lighting lighting = default_lighting(basis);
  lighting[0].coefficients = world_coefficients(*lid, 4, {0, 0, -1}, {1, 0, 0}, true);
  const Relit wanted = relight(basis, lighting);
  std::vector<FitTarget> targets;
  for (std::uint32_t p = 0; p < basis.mesh.size(); p += 3)
    if (wanted.total(p, 0) > 1) targets.push_back({p, wanted.total(p, 0)});
  BOOST_TEST_REQUIRE(targets.size() > 10u);
  const DistributionFit fit =
      fit_distribution(basis, default_lighting(basis), 0, {0, 0, -1}, targets, 6, true);
  double largest = 0;
  for (const FitTarget& t : targets) largest = std::max(largest, t.illuminance);
  BOOST_TEST(fit.max_residual < 1e-6 * largest);
  for (double c : fit.candela) BOOST_TEST(c >= 0);
  // the fitted setting relights to the targets too
  Lighting fitted = default_lighting(basis);
  fitted[0] = fit.setting;
  const Relit again = relight(basis, fitted);
  for (const FitTarget& t : targets)
    BOOST_TEST(std::abs(again.total(t.patch, 0) - t.illuminance) < 1e-4 * largest);
}

BOOST_AUTO_TEST_SUITE_END()
