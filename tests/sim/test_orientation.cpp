// Orientation helpers: ZYX angles and the rate conversion of paper 000 Eqs. 41-42, quaternions.
#include <gtest/gtest.h>

#include "rbdc/sim/orientation.hpp"

using namespace rbdc;
using namespace rbdc::sim;

TEST(Orientation, ZyxRoundTrip) {
  const Vector3 xi(0.7, -0.4, 1.1);
  EXPECT_TRUE(zyx_from_rotation(rotation_from_zyx(xi)).isApprox(xi, 1e-12));
}

TEST(Orientation, EulerRatesInvertEq41) {
  const Vector3 xi(-2.0, 0.6, 0.3), omega_W(0.4, -1.3, 2.2);
  const Vector3 rates = euler_rates(xi, omega_W);
  EXPECT_TRUE((euler_rate_matrix(xi) * rates).isApprox(omega_W, 1e-12));
}

TEST(Orientation, Eq41MatchesTheDerivativeOfTheRotation) {
  // Ṙ Rᵀ = ω̃_W for ξ moving at rate ξ̇ (finite difference of R(ξ)).
  const Vector3 xi(0.5, -0.2, 0.9), xi_rate(0.3, -0.7, 1.1);
  const double h = 1e-6;
  const Matrix3 R_dot = (rotation_from_zyx(xi + h * xi_rate) - rotation_from_zyx(xi - h * xi_rate)) / (2 * h);
  const Matrix3 w = R_dot * rotation_from_zyx(xi).transpose();
  EXPECT_TRUE(Vector3(w(2, 1), w(0, 2), w(1, 0)).isApprox(euler_rate_matrix(xi) * xi_rate, 1e-8));
}

TEST(Orientation, QuaternionRateMatchesBodyAngularVelocity) {
  const Eigen::Vector4d q = quaternion_from_rotation(rotation_from_zyx(Vector3(0.2, 0.4, -0.6)));
  const Vector3 omega_B(0.5, -0.8, 1.7);
  const double h = 1e-6;
  const Matrix3 R_next = rotation_from_quaternion(q + h * quaternion_rate(q, omega_B));
  const Matrix3 expected = rotation_from_quaternion(q) * Eigen::AngleAxisd(h * omega_B.norm(), omega_B.normalized()).toRotationMatrix();
  EXPECT_TRUE(R_next.isApprox(expected, 1e-10));
}
