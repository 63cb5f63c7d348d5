// Contact at the contact point (paper 000 Eqs. 32-33, 38): the angular rows of the foot bodies
// against the runtime's kinematics, the contact-point velocity of a rolling foot, the generalised
// force of a force at C_k (its power equals f · v_Ck), and the generated dynamics' M and J.
#include <gtest/gtest.h>

#include <random>

#include "rbdc/kinematics.hpp"
#include "rbdc/sim/contact_solver.hpp"
#include "rbdc/sim/feet_angular.hpp"
#include "rbdc/sim/robot.hpp"

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

TEST(ContactPoint, AngularRowsMatchTheRuntimeKinematics) {
  const Model model = load_robot(default_urdf());
  FeetAngularJacobian angular(model);
  std::mt19937 rng(3);
  MatrixX Jw;
  for (int trial = 0; trial < 20; ++trial) {
    const State s = random_state(model, rng, 0.3);
    angular.compute(s.q.data(), Jw);
    for (size_t k = 0; k < model.feet.size(); ++k) {
      const Vector3 expected = runtime_omega(model, s, model.feet[k].body);
      EXPECT_LT((Jw.middleRows<3>(3 * static_cast<int>(k)) * s.v - expected).norm(), 1e-12 * (1 + expected.norm()));
    }
  }
}

TEST(ContactPoint, GeneratedMassMatrixAndJacobianEqualTheRuntime) {
  const Model model = load_robot(default_urdf());
  auto runtime = make_runtime_dynamics(model);
  auto generated = make_generated_dynamics();
  std::mt19937 rng(4);
  const State s = random_state(model, rng, 0.3);
  MatrixX M1, M2, J1, J2, W1, W2;
  runtime->mass_matrix(s.q.data(), M1);
  generated->mass_matrix(s.q.data(), M2);
  runtime->feet_jacobian(s.q.data(), J1);
  generated->feet_jacobian(s.q.data(), J2);
  runtime->feet_angular_jacobian(s.q.data(), W1);
  generated->feet_angular_jacobian(s.q.data(), W2);
  EXPECT_LT((M1 - M2).norm(), 1e-10 * M1.norm());
  EXPECT_LT((J1 - J2).norm(), 1e-10 * J1.norm());
  EXPECT_LT((W1 - W2).norm(), 1e-14);
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
