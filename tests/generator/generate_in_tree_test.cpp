// rbdc_generate() inside this build: the golden two-link robot (revolute shoulder, then a prismatic
// slider of 0.5 kg carrying a massless tip) generated at build time, checked on physics it must obey.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "two_link/full.hpp"

namespace {

namespace robot = rbdc_gen::two_link::full;

TEST(GenerateInTree, PrismaticDiagonalIsTheSlidingMass) {
  robot::ConfigVector<double> q(0.7, 0.1);
  robot::MassMatrix<double> M;
  robot::mass_matrix(q, M);
  EXPECT_NEAR(M(1, 1), 0.5, 1e-15);  // only the slider moves along the prismatic axis
  EXPECT_NEAR(M(0, 1), M(1, 0), 1e-15);
  EXPECT_GT(M.determinant(), 0.0);
}

TEST(GenerateInTree, InverseDynamicsAtRestIsGravity) {
  const robot::ConfigVector<double> q(-0.4, 0.15);
  const robot::TangentVector<double> zero = robot::TangentVector<double>::Zero();
  robot::TangentVector<double> tau, g;
  robot::inverse_dynamics(q, zero, zero, tau);
  robot::gravity_terms(q, g);
  EXPECT_TRUE(tau.isApprox(g, 1e-14));
  EXPECT_GT(g.norm(), 0.0);
}

}  // namespace
