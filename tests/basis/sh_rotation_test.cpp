// Rotation of SH coefficient vectors: against direct evaluation of the rotated
// function, the zonal formula about the new axis, composition and inverse.

#include "penumbra/basis/sh_rotation.h"

#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "penumbra/basis/distribution_fit.h"
#include "penumbra/basis/spherical_harmonics.h"
#include "penumbra/photometry/orientation.h"

using namespace penumbra::basis;

namespace {

// Fixed seeds: the same rotations, coefficients and directions on every run.
Eigen::Matrix3d random_rotation(std::mt19937& random) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return q.normalized().toRotationMatrix();
}

Eigen::Vector3d random_direction(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
}

Eigen::VectorXd random_coefficients(int degree, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd c(sh_count(degree));
  for (Eigen::Index i = 0; i < c.size(); ++i) c[i] = uniform(random);
  return c;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sh_rotation)

BOOST_AUTO_TEST_CASE(rotated_coefficients_evaluate_the_rotated_function) {
  std::mt19937 random(11);
  for (int degree : {1, 3, 8, 12}) {
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Eigen::VectorXd c = random_coefficients(degree, random);
    const Eigen::VectorXd rotated = rotate_sh(c, rotation);
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector3d d = random_direction(random);
      BOOST_TEST(
          std::abs(evaluate_sh(rotated, d) - evaluate_sh(c, rotation.transpose() * d)) <= 1e-12,
          "degree " << degree);
    }
  }
}

BOOST_AUTO_TEST_CASE(rotating_a_zonal_lamp_equals_the_legendre_series_about_the_new_axis) {
  // A lamp aimed along z, rotated by R, is the lamp aimed along R z (eqs. 8-10).
  const std::vector<double> w{100, 150, 90, 20, -10, -5, 3, 2, -1};
  std::mt19937 random(12);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Eigen::VectorXd rotated =
        ShRotation(8, rotation).apply(zonal_sh_coefficients(w, Eigen::Vector3d::UnitZ()));
    const Eigen::VectorXd direct = zonal_sh_coefficients(w, rotation.col(2));
    BOOST_TEST((rotated - direct).cwiseAbs().maxCoeff() <= 1e-12);
  }
  // rotation_taking_z_to aims the lamp, including straight down.
  for (const Eigen::Vector3d& axis :
       {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 1, -2), Eigen::Vector3d(0, 0, 1)}) {
    const Eigen::Matrix3d aim = rotation_taking_z_to(axis);
    BOOST_TEST((aim * Eigen::Vector3d::UnitZ() - axis.normalized()).norm() <= 4e-15);
    BOOST_TEST(aim.determinant() == 1.0, boost::test_tools::tolerance(1e-14));
  }
}

BOOST_AUTO_TEST_CASE(composition_and_inverse) {
  std::mt19937 random(13);
  const int degree = 8;
  const Eigen::Matrix3d a = random_rotation(random), b = random_rotation(random);
  const Eigen::MatrixXd da = ShRotation(degree, a).matrix(), db = ShRotation(degree, b).matrix();
  const Eigen::MatrixXd dab = ShRotation(degree, a * b).matrix();
  BOOST_TEST((da * db - dab).cwiseAbs().maxCoeff() <= 1e-13);
  const Eigen::MatrixXd inverse = ShRotation(degree, a.transpose()).matrix();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(sh_count(degree), sh_count(degree));
  BOOST_TEST((inverse * da - identity).cwiseAbs().maxCoeff() <= 1e-13);
  BOOST_TEST((inverse - da.transpose()).cwiseAbs().maxCoeff() <= 1e-13);
  BOOST_TEST(
      (ShRotation(degree, Eigen::Matrix3d::Identity()).matrix() - identity).cwiseAbs().maxCoeff() <=
      1e-13);
}

BOOST_AUTO_TEST_CASE(about_z_mixes_cos_and_sin_pairs_by_m_alpha) {
  // A turn by alpha about z maps (Y_lm, Y_l,-m) coefficients (c, s) to
  // (c cos m alpha - s sin m alpha, c sin m alpha + s cos m alpha): f(R^T d) shifts phi.
  const double alpha = 0.83;
  const ShRotation turn(4, Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  for (int l = 1; l <= 4; ++l)
    for (int m = 1; m <= l; ++m) {
      const Eigen::MatrixXd& band = turn.band(l);
      BOOST_TEST(std::abs(band(l + m, l + m) - std::cos(m * alpha)) <= 1e-14);
      BOOST_TEST(std::abs(band(l - m, l + m) - std::sin(m * alpha)) <= 1e-14);
      BOOST_TEST(std::abs(band(l + m, l - m) + std::sin(m * alpha)) <= 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(photometric_frame_agrees_with_the_photometry_layer) {
  // The photometric frame maps (sin g cos C, sin g sin C, cos g) to the world
  // direction that photometry::world_direction gives; it is a reflection (det -1),
  // and ShRotation handles it.
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.3, -0.9).normalized();
  const Eigen::Vector3d c0 = axis.unitOrthogonal();
  const Eigen::Matrix3d frame = photometric_frame(axis, c0);
  BOOST_TEST(frame.determinant() == -1.0, boost::test_tools::tolerance(1e-14));
  for (double gamma : {0.1, 1.0, 2.5})
    for (double c : {0.0, 0.7, 2.0, 4.5}) {
      const Eigen::Vector3d local(std::sin(gamma) * std::cos(c), std::sin(gamma) * std::sin(c),
                                  std::cos(gamma));
      const auto world = penumbra::photometry::world_direction(
          {axis.x(), axis.y(), axis.z()}, {c0.x(), c0.y(), c0.z()}, {gamma, c});
      BOOST_TEST((frame * local - Eigen::Vector3d(world[0], world[1], world[2])).norm() <= 1e-14);
    }
  std::mt19937 random(14);
  const Eigen::VectorXd c = random_coefficients(5, random);
  const Eigen::VectorXd world = rotate_sh(c, frame);
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d d = random_direction(random);
    BOOST_TEST(std::abs(evaluate_sh(world, d) - evaluate_sh(c, frame.transpose() * d)) <= 1e-12);
  }
}

BOOST_AUTO_TEST_SUITE_END()
