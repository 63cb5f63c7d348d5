// Split RNEA terms against independent routes:
//  - g (Alg. 3) as the gradient of the potential energy, by finite differences;
//  - c (Alg. 2) from the Lagrangian (Euler-Poincaré for the trunk twist, Lagrange for the joints):
//      c = M δ + Ṁ v + [v_B ×* (M v)_B ; -½ vᵀ ∂M/∂q_j v],   δ = ((0, -ω × v_B), 0),
//    where δ turns the classical trunk acceleration of our convention into d v/dt, and Ṁ, ∂M/∂q_j
//    come from finite differences of the CRBA (M depends on the joint angles only);
//  - τ_e (Alg. 4) as Jᵀ f (App. B) and, for body wrenches, by virtual power fᵀ v_i(e_k).
#include <gtest/gtest.h>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

class BiasTerms : public ::testing::TestWithParam<int> {
 protected:
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  test::RandomState random{31u + static_cast<unsigned>(GetParam())};

  double potential_energy(const VectorX& q) {
    world_transforms(model, data, q);
    double U = 0;
    for (int i = 0; i < model.nb; ++i) {
      const Matrix6& X = data.X_world[static_cast<size_t>(i)];
      const Matrix3 world_R_body = X.topLeftCorner<3, 3>().transpose();
      const Matrix3 r_tilde = -world_R_body * X.bottomLeftCorner<3, 3>();  // origin of i, world
      const Vector3 origin(r_tilde(2, 1), r_tilde(0, 2), r_tilde(1, 0));
      const Body& b = model.bodies[static_cast<size_t>(i)];
      U -= b.mass * model.gravity.dot(origin + world_R_body * b.com);
    }
    return U;
  }
};

TEST_P(BiasTerms, GravityTermsAreTheGradientOfPotentialEnergy) {
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX g = gravity_terms(model, data, q);
    for (int k = 0; k < model.nv; ++k) {
      const VectorX step = h * VectorX::Unit(model.nv, k);
      const double fd = (potential_energy(test::integrate(model, q, step)) -
                         potential_energy(test::integrate(model, q, -step))) / (2 * h);
      EXPECT_NEAR(g[k], fd, 1e-7 * (1 + g.norm())) << "entry " << k;
    }
  }
}

TEST_P(BiasTerms, QuadraticVelocityTermsFollowFromTheLagrangian) {
  const double h = 1e-6;
  const int first_joint = model.root_dofs();
  const int q_offset = model.floating_base ? 7 : 0;
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 3.0);
    const MatrixX M = mass_matrix(model, data, q);
    // ∂M/∂q_j for every joint j, by central differences
    std::vector<MatrixX> dM(static_cast<size_t>(model.num_joints()));
    MatrixX M_dot = MatrixX::Zero(model.nv, model.nv);
    for (int j = 0; j < model.num_joints(); ++j) {
      VectorX q_plus = q, q_minus = q;
      q_plus[q_offset + j] += h;
      q_minus[q_offset + j] -= h;
      const MatrixX M_plus = mass_matrix(model, data, q_plus);  // a copy: the result lives in data
      dM[static_cast<size_t>(j)] = (M_plus - mass_matrix(model, data, q_minus)) / (2 * h);
      M_dot += dM[static_cast<size_t>(j)] * v[first_joint + j];
    }
    VectorX delta = VectorX::Zero(model.nv);
    if (model.floating_base) delta.segment<3>(3) = -v.head<3>().cross(v.segment<3>(3));
    const VectorX momentum = M * v;
    VectorX expected = M * delta + M_dot * v;
    if (model.floating_base) expected.head<6>() += crf(v.head<6>()) * momentum.head<6>();
    for (int j = 0; j < model.num_joints(); ++j) {
      expected[first_joint + j] -= 0.5 * v.dot(dM[static_cast<size_t>(j)] * v);
    }
    const VectorX c = quadratic_velocity_terms(model, data, q, v);
    EXPECT_LE((c - expected).norm(), 1e-7 * (1 + c.norm())) << "c = " << c.transpose() << "\nexpected " << expected.transpose();
  }
}

TEST_P(BiasTerms, FeetForceTermsEqualJacobianTransposeTimesForces) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const Matrix3X f = random.forces(model);
    const VectorX tau_e = feet_force_terms(model, data, q, f);
    const VectorX JT_f = feet_jacobian(model, data, q).transpose() * Eigen::Map<const VectorX>(f.data(), f.size());
    EXPECT_LE((tau_e - JT_f).norm(), 1e-12 * (1 + JT_f.norm()));
  }
}

TEST_P(BiasTerms, BodyWrenchTermsEqualVirtualPower) {
  for (int trial = 0; trial < 10; ++trial) {
    const VectorX q = random.configuration(model);
    std::vector<Vector6> f_ext(static_cast<size_t>(model.nb));
    for (Vector6& f : f_ext) f = random.vector(6, 10.0);
    const VectorX tau_e = external_wrench_terms(model, data, q, f_ext);
    for (int k = 0; k < model.nv; ++k) {
      kinematics(model, data, q, VectorX::Unit(model.nv, k));  // body twists for v = e_k
      double power = 0;
      for (size_t i = 0; i < f_ext.size(); ++i) power += f_ext[i].dot(data.v[i]);
      EXPECT_NEAR(tau_e[k], power, 1e-12 * (1 + tau_e.norm())) << "entry " << k;
    }
  }
}

TEST(BiasTermsFixedBase, OnlyJointEntriesAndGravityOfAWeldedRoot) {
  const Model model = test::arm7();
  Data data(model);
  EXPECT_EQ(gravity_terms(model, data, VectorX::Zero(model.nq)).size(), 7);
  // At rest c vanishes (v = 0, the welded root has no velocity of its own).
  EXPECT_EQ(quadratic_velocity_terms(model, data, VectorX::Ones(model.nq), VectorX::Zero(model.nv)).norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Robots, BiasTerms, ::testing::Range(0, 4));

}  // namespace
}  // namespace rbdc
