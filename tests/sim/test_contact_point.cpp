// Contact at the contact point (paper 000 Eqs. 32-33, 38): the step terms (angular rows of the foot
// bodies against the runtime's kinematics, generated against runtime), the generated M, and the
// generalised force of a force at C_k (its power equals f · v_Ck).
#include <gtest/gtest.h>

#include <random>

#include "rbdc/kinematics.hpp"
#include "rbdc/sim/contact_solver.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

using namespace rbdc;
using namespace rbdc::sim;

namespace {

struct State {
  VectorX q, v;
};

State random_state(const Model& model, std::mt19937& rng, double height) {
  std::uniform_real_distribution<double> unit(-1, 1);
  State s{VectorX::Zero(model.nq), VectorX::Zero(model.nv)};
  s.q[2] = height;
  s.q.segment<4>(3) = Eigen::Vector4d(1 + 0.2 * unit(rng), 0.1 * unit(rng), 0.1 * unit(rng), 0.1 * unit(rng)).normalized();
  for (int i = 7; i < model.nq; ++i) s.q[i] = 0.8 * unit(rng);
  for (int i = 0; i < model.nv; ++i) s.v[i] = unit(rng);
  return s;
}

// World angular velocity of body i from the runtime: X_W^i's rotation is i_R_W.
Vector3 runtime_omega(const Model& model, const State& s, int body) {
  Data data(model);
  kinematics(model, data, s.q, s.v);
  const std::vector<Matrix6>& X = world_transforms(model, data, s.q);
  return X[static_cast<size_t>(body)].topLeftCorner<3, 3>().transpose() * data.v[static_cast<size_t>(body)].head<3>();
}

}  // namespace

// The step terms (feet, their linear and angular rows, M's factor, a₀) of the runtime and the
// generated code: the angular rows and velocities against the runtime's body kinematics, then each
// term generated against the runtime's.
TEST(ContactPoint, StepTermsMatchTheRuntimeKinematics) {
  const Model model = load_robot(default_urdf());
  auto runtime = make_runtime_dynamics(model);
  auto generated = make_generated_dynamics();
  std::mt19937 rng(3);
  StepTerms r, g;
  TreeLtdl factor_r(dof_parents(model)), factor_g(dof_parents(model));
  for (int trial = 0; trial < 20; ++trial) {
    const State s = random_state(model, rng, 0.3);
    const VectorX tau = 5 * s.v.tail(model.nv - 6);
    runtime->step_terms(s.q.data(), s.v.data(), tau.data(), r, factor_r);
    generated->step_terms(s.q.data(), s.v.data(), tau.data(), g, factor_g);
    for (size_t k = 0; k < model.feet.size(); ++k) {
      const int row = 3 * static_cast<int>(k);
      const Vector3 expected = runtime_omega(model, s, model.feet[k].body);
      EXPECT_LT((r.Jw.middleRows<3>(row) * s.v - expected).norm(), 1e-12 * (1 + expected.norm()));
      EXPECT_LT((r.omega_feet.col(static_cast<int>(k)) - expected).norm(), 1e-12 * (1 + expected.norm()));
    }
    EXPECT_LT((g.p_feet - r.p_feet).norm(), 1e-12 * r.p_feet.norm());
    EXPECT_LT((g.v_feet - r.v_feet).norm(), 1e-12 * r.v_feet.norm());
    EXPECT_LT((g.omega_feet - r.omega_feet).norm(), 1e-12 * r.omega_feet.norm());
    EXPECT_LT((g.J - r.J).norm(), 1e-12 * r.J.norm());
    EXPECT_LT((g.Jw - r.Jw).norm(), 1e-14);
    EXPECT_LT((g.a_free - r.a_free).norm(), 1e-12 * r.a_free.norm());
    EXPECT_LT((factor_g.inverse_pivots() - factor_r.inverse_pivots()).norm(), 1e-12 * factor_r.inverse_pivots().norm());
  }
}

TEST(ContactPoint, GeneratedMassMatrixEqualsTheRuntime) {
  const Model model = load_robot(default_urdf());
  auto runtime = make_runtime_dynamics(model);
  auto generated = make_generated_dynamics();
  std::mt19937 rng(4);
  const State s = random_state(model, rng, 0.3);
  MatrixX M1, M2;
  runtime->mass_matrix(s.q.data(), M1);
  generated->mass_matrix(s.q.data(), M2);
  EXPECT_LT((M1 - M2).norm(), 1e-10 * M1.norm());
}

// A robot whose feet are pressed into the ground: the contact forces act at C_k, so their power
// M (a − a₀) · v equals Σ f_k · v_Ck with v_Ck = v_fk + ω_k × (−r ẑ) from the runtime kinematics.
TEST(ContactPoint, ForceAtTheContactPointDoesThePowerOfItsVelocity) {
  const Model model = load_robot(default_urdf());
  auto dynamics = make_runtime_dynamics(model);
  std::mt19937 rng(8);
  for (FrictionUpdate update : {FrictionUpdate::Explicit, FrictionUpdate::Implicit}) {
    ContactParameters p;
    p.friction_update = update;
    const GroundPlane ground;
    State s = random_state(model, rng, 0.3);
    s.v *= 0.01;  // slow, so that friction is partly in the stiction band
    Data data(model);
    const Matrix3X feet = feet_positions(model, data, s.q);
    s.q[2] -= feet.row(2).minCoeff() - p.foot_radius + 0.05e-3;  // lowest foot 0.05 mm deep
    const VectorX tau = VectorX::Zero(model.nv - 6);
    ContactSolver solver;
    Matrix3X p_feet(3, 4), v_feet(3, 4), f_feet(3, 4), zero = Matrix3X::Zero(3, 4);
    std::vector<FootContact> contacts(4);
    VectorX a(model.nv), a0(model.nv);
    solver.accelerations(*dynamics, p, ground, 1e-4, s.q, s.v, tau, p_feet, v_feet, contacts, f_feet, a);
    dynamics->forward_dynamics(s.q.data(), s.v.data(), tau.data(), zero.data(), a0.data());
    MatrixX M;
    dynamics->mass_matrix(s.q.data(), M);
    double power = 0;
    int active = 0;
    for (size_t k = 0; k < 4; ++k) {
      if (!contacts[k].active) continue;
      ++active;
      const Vector3 v_C = v_feet.col(static_cast<int>(k)) +
                          runtime_omega(model, s, model.feet[k].body).cross(Vector3(0, 0, -p.foot_radius));
      power += contacts[k].force_W.dot(v_C);
    }
    ASSERT_GE(active, 1);
    EXPECT_NEAR((M * (a - a0)).dot(s.v), power, 1e-9 * (1 + std::abs(power)));
  }
}
