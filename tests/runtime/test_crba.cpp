// Joint-space inertia (Alg. 5) against the RNEA: symmetry, positive definiteness, columns from
// unit accelerations, and inverse dynamics = M a + c + g.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

class Crba : public ::testing::TestWithParam<int> {
 protected:
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  test::RandomState random{123u + static_cast<unsigned>(GetParam())};
};

TEST_P(Crba, MassMatrixIsSymmetricPositiveDefinite) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const MatrixX M = mass_matrix(model, data, q);
    EXPECT_EQ((M - M.transpose()).cwiseAbs().maxCoeff(), 0.0);
    Eigen::SelfAdjointEigenSolver<MatrixX> eigen(M);
    EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0) << "q = " << q.transpose();
  }
}

TEST_P(Crba, ColumnsEqualInverseDynamicsOfUnitAccelerations) {
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const MatrixX M = mass_matrix(model, data, q);
    const VectorX bias = inverse_dynamics(model, data, q, v, VectorX::Zero(model.nv));
    for (int k = 0; k < model.nv; ++k) {
      const VectorX column =
          inverse_dynamics(model, data, q, v, VectorX::Unit(model.nv, k)) - bias;
      EXPECT_LE((column - M.col(k)).norm(), 1e-12 * (1 + M.col(k).norm())) << "column " << k;
    }
  }
}

TEST_P(Crba, InverseDynamicsEqualsMassMatrixTimesAccelerationPlusBiasTerms) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 3.0);
    const VectorX a = random.vector(model.nv, 10.0);
    const VectorX split = mass_matrix(model, data, q) * a +
                          quadratic_velocity_terms(model, data, q, v) + gravity_terms(model, data, q);
    const VectorX tau = inverse_dynamics(model, data, q, v, a);
    EXPECT_LE((tau - split).norm(), 1e-12 * tau.norm());
  }
}

TEST_P(Crba, TrunkBlockIsTheTotalCompositeInertia) {
  if (!model.floating_base) GTEST_SKIP() << "fixed base: no trunk block";
  double total_mass = 0;
  for (const Body& b : model.bodies) total_mass += b.mass;
  const MatrixX M = mass_matrix(model, data, random.configuration(model));
  // I_c0's linear block is m_total·1 in any configuration (Eq. 29).
  EXPECT_NEAR(M(3, 3), total_mass, 1e-12);
  EXPECT_NEAR(M(5, 5), total_mass, 1e-12);
  EXPECT_NEAR(M(3, 4), 0.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Robots, Crba, ::testing::Range(0, 4));

}  // namespace
}  // namespace rbdc
