// Form factors and the radiosity system (Dobashi 1995 eq. 14): Siegel and Howell's
// parallel squares, closure, the Jacobi solver against a dense LU solve, and CIE 171:2006
// test case 5.8 (the integrating cube).

#include <Eigen/Dense>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "penumbra/base/gauss_legendre.h"
#include "penumbra/base/numbers.h"
#include "penumbra/basis/basis_luminances.h"
#include "penumbra/basis/form_factors.h"
#include "penumbra/basis/patch_mesh.h"
#include "penumbra/basis/radiosity.h"
#include "penumbra/basis/scene_radiosity.h"
#include "radiosity_scenes.h"

using penumbra::pi;
using namespace penumbra;
using namespace penumbra::basis;

namespace {

// Siegel and Howell, Thermal Radiation Heat Transfer, configuration C-11 (Howell's
// catalogue): two directly opposed parallel unit squares at distance 1. The closed form
// (X = Y = 1) is F = 2/(pi X Y) { ln sqrt((1+X^2)(1+Y^2)/(1+X^2+Y^2))
//   + X sqrt(1+Y^2) atan(X/sqrt(1+Y^2)) + Y sqrt(1+X^2) atan(Y/sqrt(1+X^2)) - X atan X - Y atan Y
//   }.
double opposed_unit_squares() {
  const double X = 1, Y = 1;
  const double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
  return 2 / (pi * X * Y) *
         (std::log(std::sqrt((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y))) +
          X * b * std::atan(X / b) + Y * a * std::atan(Y / a) - X * std::atan(X) -
          Y * std::atan(Y));
}

// two flat unit squares facing each other: z = 0 facing up, z = 1 facing down
Scene opposed_squares_scene() {
  return parse_scene(R"({"penumbra": 1, "materials": {"m": {"reflectance": 0.5}}, "objects": [
    {"name": "low", "material": "m", "polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]},
    {"name": "high", "material": "m", "polygon": [[0,0,1],[1,0,1],[1,1,1],[0,1,1]]}],
    "lights": []})",
                     "squares.json");
}

// F between the upward face of "low" and the downward face of "high" in a form factor
// matrix of one patch per face.
double square_to_square(const PatchMesh& mesh, const FormFactorMatrix& F) {
  std::optional<std::size_t> up, down;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Patch& p = mesh.patches()[i];
    if (p.object == 0 && p.normal[2] > 0.5) up = i;
    if (p.object == 1 && p.normal[2] < -0.5) down = i;
  }
  BOOST_REQUIRE(up && down);
  return F.coeff(static_cast<std::int64_t>(*up), static_cast<std::int64_t>(*down));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(radiosity)

BOOST_AUTO_TEST_CASE(closed_form_is_siegel_howell_value) {
  // the tabulated value the issue quotes, to its five decimals
  BOOST_TEST(std::abs(opposed_unit_squares() - 0.19982) < 5e-6);
}

BOOST_AUTO_TEST_CASE(point_polygon_form_factor_integrates_to_the_area_form_factor) {
  // (1/A_1) int_{A_1} F_{dA -> A_2} dA by a 20 x 20 Gauss-Legendre product rule: the
  // point-to-polygon formula is exact for a differential area, so the area average must
  // reproduce the closed form
  const auto rule = gauss_legendre(20);
  const std::vector<Vec3d> square = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  double average = 0;
  for (std::size_t a = 0; a < rule.nodes.size(); ++a)
    for (std::size_t b = 0; b < rule.nodes.size(); ++b) {
      const Vec3d point{(rule.nodes[a] + 1) / 2, (rule.nodes[b] + 1) / 2, 0};
      average += rule.weights[a] * rule.weights[b] / 4 *
                 point_polygon_form_factor(point, {0, 0, 1}, square);
    }
  BOOST_TEST(average == opposed_unit_squares(), boost::test_tools::tolerance(1e-9));
  // a differential area facing a parallel rectangle a x b at height h, its normal
  // through a corner (Howell's catalogue, B-3; A = a/h, B = b/h):
  //   F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))];
  // under the centre of the unit square at h = 1 it is four such rectangles with A = B = 1/2
  const double A = 0.5, root = std::sqrt(1 + A * A);
  const double corner = 1 / (2 * pi) * 2 * (A / root) * std::atan(A / root);
  BOOST_TEST(point_polygon_form_factor({0.5, 0.5, 0}, {0, 0, 1}, square) == 4 * corner,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(point_form_factors_close_around_an_interior_point) {
  // the six faces of a cube seen from a point of its floor cover the hemisphere: sum 1
  const Vec3d p{0.3, 0.6, 0};
  const std::vector<std::vector<Vec3d>> faces = {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                                                 {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}},
                                                 {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
                                                 {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
                                                 {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}};
  double sum = 0;
  for (const auto& face : faces) sum += point_polygon_form_factor(p, {0, 0, 1}, face);
  BOOST_TEST(sum == 1.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(ray_form_factors_estimate_the_area_form_factor) {
  const Scene scene = opposed_squares_scene();
  const PatchMesh mesh = PatchMesh::subdivide(scene, 2);  // one patch per face
  FormFactorOptions options;
  options.rays = 1024 * 1024;
  const double estimate = square_to_square(mesh, form_factors(scene, mesh, options));
  // each ray hits the other square or not: binomial standard deviation sqrt(F (1 - F) / K)
  // = 3.9e-4 for K = 2^20 rays (stratification narrows it little here: 2.8e-4 over seeds
  // 1..12); three of it is 1.2e-3
  const double sigma =
      std::sqrt(opposed_unit_squares() * (1 - opposed_unit_squares()) / options.rays);
  BOOST_TEST(std::abs(estimate - opposed_unit_squares()) < 3 * sigma);
  // the centre-to-square value (0.2395) is far: origins must cover the patch
  BOOST_TEST(std::abs(estimate - point_polygon_form_factor(
                                     {0.5, 0.5, 0}, {0, 0, 1},
                                     {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}})) > 0.03);
  // the same seed gives the same estimate whatever the threads
  options.parallel = false;
  BOOST_TEST(square_to_square(mesh, form_factors(scene, mesh, options)) == estimate);
}

BOOST_AUTO_TEST_CASE(analytic_form_factors_converge_with_subdivision) {
  const Scene scene = opposed_squares_scene();
  FormFactorOptions options;
  options.method = FormFactorMethod::analytic;
  // area-weighted sum of the centre-to-patch factors from all low patches to all high
  // patches: O(h^2) convergence to the area form factor
  const auto total = [&](double size) {
    const PatchMesh mesh = PatchMesh::subdivide(scene, size);
    const FormFactorMatrix F = form_factors(scene, mesh, options);
    double sum = 0, area = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) {
      const Patch& p = mesh.patches()[i];
      if (p.object != 0 || p.normal[2] < 0.5) continue;
      area += p.area;
      for (FormFactorMatrix::InnerIterator e(F, static_cast<std::int64_t>(i)); e; ++e)
        if (mesh.patches()[static_cast<std::size_t>(e.col())].object == 1)
          sum += p.area * e.value();
    }
    return std::abs(sum / area - opposed_unit_squares());
  };
  const double coarse = total(0.25), fine = total(0.125);
  BOOST_TEST(coarse < 5e-3);
  BOOST_TEST(fine < coarse / 3);  // second order: a quarter, give or take
}

BOOST_AUTO_TEST_CASE(jacobi_matches_a_dense_solve) {
  // a random 60-patch system with row sums 0.99 and reflectances up to 0.95
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  const int n = 60, columns = 5;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      if (i != j && uniform(random) < 0.5) dense(i, j) = uniform(random);
    dense.row(i) *= 0.99 / dense.row(i).sum();
  }
  Eigen::VectorXd rho(n);
  for (int i = 0; i < n; ++i) rho[i] = 0.95 * uniform(random);
  rho[0] = 0.95;
  Eigen::MatrixXd direct(n, columns);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < columns; ++c)
      direct(i, c) = uniform(random) - 0.3;  // SH columns change sign
  FormFactorMatrix F = dense.sparseView();
  RadiosityOptions options;
  options.tolerance = 1e-12;
  const RadiosityResult result = solve_radiosity(F, rho, direct, options);
  BOOST_TEST(result.converged);
  const Eigen::MatrixXd expected =
      (Eigen::MatrixXd::Identity(n, n) - dense * rho.asDiagonal()).partialPivLu().solve(direct);
  BOOST_TEST((result.illuminance - expected).cwiseAbs().maxCoeff() <
             1e-9 * expected.cwiseAbs().maxCoeff());
}

BOOST_AUTO_TEST_CASE(cie_171_test_5_8_integrating_cube) {
  // CIE 171:2006 test case 5.8: a 4 m cube, an isotropic 10,000 lm source at its centre;
  // the average indirect illuminance of the walls is rho Phi / (S (1 - rho)), S = 96 m^2.
  // Derivation for our discretisation: with closure (sum_j F_ij = 1) and reciprocity
  // (A_i F_ij = A_j F_ji) the area-weighted mean of E - E_direct is rho Phi_d / (S (1 - rho))
  // where Phi_d = sum_i A_i E_direct,i is the flux the patch centres sample. We check the
  // discretised flux against Phi and the indirect mean against the CIE formula with both.
  const double flux = 10000, S = 96;
  for (double rho : {0.05, 0.2, 0.5, 0.8, 0.95}) {
    const Scene scene = test::closed_room(4, rho,
                                          R"({"name": "bulb", "point": [2, 2, 2], "candela": )" +
                                              std::to_string(flux / (4 * pi)) + "}");
    BasisOptions options;
    options.patch_size = 0.5;
    options.form_factors.method = FormFactorMethod::rays;
    options.form_factors.rays = 1024;
    options.radiosity.tolerance = 1e-9;
    const SceneRadiosity solved = solve_scene_radiosity(scene, options);
    double direct_flux = 0, indirect_flux = 0;
    for (std::size_t i = 0; i < solved.mesh.size(); ++i) {
      const Patch& p = solved.mesh.patches()[i];
      // the inner faces: centres on the cube's boundary, normals pointing in
      using namespace vector_ops;
      if (dot(p.normal, Vec3d{2, 2, 2} - p.centre) <= 0) continue;
      if (std::max({std::abs(p.centre[0] - 2), std::abs(p.centre[1] - 2),
                    std::abs(p.centre[2] - 2)}) > 2.0001)
        continue;
      const auto row = static_cast<Eigen::Index>(i);
      direct_flux += p.area * solved.direct_per_light(row, 0);
      indirect_flux += p.area * (solved.total(row, 0) - solved.direct_per_light(row, 0));
    }
    BOOST_TEST_CONTEXT("rho " << rho) {
      // centre sampling of the direct flux at 0.5 m patches (exact integral: flux)
      BOOST_TEST(direct_flux == flux, boost::test_tools::tolerance(5e-3));
      const double expected = rho * flux / (S * (1 - rho));
      BOOST_TEST(indirect_flux / S == expected, boost::test_tools::tolerance(1e-2));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
