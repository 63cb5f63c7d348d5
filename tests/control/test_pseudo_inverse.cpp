// Eq. 55's pseudo-inverse: singular values below σ_max/100 are dropped, the others inverted.
#include <gtest/gtest.h>

#include <Eigen/QR>

#include "rbdc/control/pseudo_inverse.hpp"

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// A random orthogonal matrix from the QR factorisation of a random matrix.
Matrix6 random_orthogonal(int seed) {
  std::srand(seed);
  return Eigen::HouseholderQR<Matrix6>(Matrix6::Random()).householderQ();
}

TEST(PseudoInverse, DropsSingularValuesBelowOneHundredthOfTheLargest) {
  const Matrix6 U = random_orthogonal(1), V = random_orthogonal(2);
  const Vector6 sigma = (Vector6() << 10, 4, 0.5, 0.11, 0.09, 1e-6).finished();
  const Matrix6 A = U * sigma.asDiagonal() * V.transpose();
  const Vector6 y = Vector6::Random();
  int rank = -1;
  const Vector6 x = rbdc::control::truncated_pseudo_inverse_solve<6, 6>(A, y, 1.0 / 100, &rank);
  // Kept: 10, 4, 0.5, 0.11 (≥ 0.1); dropped: 0.09 and 1e-6.
  EXPECT_EQ(rank, 4);
  Vector6 inverse_sigma = Vector6::Zero();
  inverse_sigma.head<4>() = sigma.head<4>().cwiseInverse();
  const Vector6 expected = V * inverse_sigma.asDiagonal() * U.transpose() * y;
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
  // The dropped directions get nothing: x has no component along v_5, v_6.
  EXPECT_NEAR(V.col(4).dot(x), 0, 1e-10);
  EXPECT_NEAR(V.col(5).dot(x), 0, 1e-10);
}

TEST(PseudoInverse, SolvesWellConditionedSystemsExactly) {
  const Matrix6 A = Matrix6::Random() + 6 * Matrix6::Identity();
  const Vector6 x_true = Vector6::Random();
  int rank = -1;
  const Vector6 x = rbdc::control::truncated_pseudo_inverse_solve<6, 6>(A, A * x_true, 1.0 / 100, &rank);
  EXPECT_EQ(rank, 6);
  EXPECT_LT((x - x_true).norm(), 1e-12);
}

TEST(PseudoInverse, WideMatrixGivesTheMinimumNormSolution) {
  Eigen::Matrix<double, 2, 4> A;
  A << 1, 0, 1, 0, 0, 2, 0, 2;
  const Eigen::Vector2d y(2, 4);
  const Eigen::Vector4d x = rbdc::control::truncated_pseudo_inverse_solve<2, 4>(A, y);
  EXPECT_LT((x - Eigen::Vector4d(1, 1, 1, 1)).norm(), 1e-12);
}

TEST(PseudoInverse, ZeroMatrixGivesZero) {
  int rank = -1;
  const Vector6 x = rbdc::control::truncated_pseudo_inverse_solve<6, 6>(Matrix6::Zero(), Vector6::Ones(), 0.01, &rank);
  EXPECT_EQ(rank, 0);
  EXPECT_EQ(x, Vector6::Zero());
}

}  // namespace
