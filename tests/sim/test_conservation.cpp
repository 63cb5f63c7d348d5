// Without gravity and contact a free-floating Mini Cheetah with moving joints keeps its spatial
// momentum and (with zero joint torques) its kinetic energy. RK4, dt = 1e-4 s, 1 s.
// Bounds: relative drift of energy and momentum below 1e-8 (RK4's local error is O(dt⁵); measured
// drifts are orders of magnitude smaller).
#include <gtest/gtest.h>

#include "rbdc/crba.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/simulator.hpp"

using namespace rbdc;
using namespace rbdc::sim;

namespace {

// h = Σ_i X̄_i^W I_i v_i = Σ_i (X_W^i)ᵀ I_i v_i (Eq. 8), world coordinates at the world origin.
Vector6 spatial_momentum(const Model& model, Data& data, const VectorX& q, const VectorX& v) {
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  Vector6 h = Vector6::Zero();
  for (int i = 0; i < model.nb; ++i) h += data.X_world[i].transpose() * model.inertia[i] * data.v[i];
  return h;
}

double kinetic_energy(const Model& model, Data& data, const VectorX& q, const VectorX& v) {
  return 0.5 * v.dot(mass_matrix(model, data, q) * v);
}

}  // namespace

TEST(Conservation, FreeFloatingMomentumAndEnergy) {
  Model model = load_robot(default_urdf());
  model.gravity.setZero();
  const auto dynamics = make_runtime_dynamics(model);
  SimOptions options;
  options.integrator = Integrator::RK4;
  options.contact_enabled = false;
  Simulator sim(*dynamics, options);

  VectorX q = VectorX::Zero(model.nq), v = VectorX::Zero(model.nv);
  q[3] = 1;
  for (int j = 0; j < model.nv - 6; ++j) {
    q[7 + j] = 0.3 * std::sin(1.0 + j);
    v[6 + j] = 2.0 * std::cos(0.5 + 2 * j);  // several rad/s in every joint
  }
  v.head<6>() << 0.3, -0.2, 0.5, 0.1, 0.05, -0.2;
  sim.reset(q, v);

  Data data(model);
  const Vector6 h0 = spatial_momentum(model, data, q, v);
  const double e0 = kinetic_energy(model, data, q, v);
  const VectorX no_torque = VectorX::Zero(model.nv - 6);
  double max_h_drift = 0, max_e_drift = 0;
  for (int n = 0; n < 10000; ++n) {
    sim.step(no_torque);
    if (n % 100 == 99) {
      max_h_drift = std::max(max_h_drift, (spatial_momentum(model, data, sim.q(), sim.v()) - h0).norm() / h0.norm());
      max_e_drift = std::max(max_e_drift, std::abs(kinetic_energy(model, data, sim.q(), sim.v()) - e0) / e0);
    }
  }
  EXPECT_LT(max_h_drift, 1e-8);
  EXPECT_LT(max_e_drift, 1e-8);
  // The joints did move: the test is not a trivially resting robot.
  EXPECT_GT((sim.q().tail(model.nv - 6) - q.tail(model.nv - 6)).norm(), 0.5);
  std::printf("momentum drift %.2e, energy drift %.2e (relative, max over 1 s)\n", max_h_drift, max_e_drift);
}

TEST(Conservation, InternalTorquesKeepMomentum) {
  // Joint torques are internal: momentum is still conserved while energy changes.
  Model model = load_robot(default_urdf());
  model.gravity.setZero();
  const auto dynamics = make_runtime_dynamics(model);
  SimOptions options;
  options.integrator = Integrator::RK4;
  options.contact_enabled = false;
  Simulator sim(*dynamics, options);
  VectorX q = VectorX::Zero(model.nq), v = VectorX::Zero(model.nv);
  q[3] = 1;
  v.head<6>() << 0.2, 0.1, -0.3, 0.2, 0.0, 0.1;
  sim.reset(q, v);
  Data data(model);
  const Vector6 h0 = spatial_momentum(model, data, q, v);
  const double e0 = kinetic_energy(model, data, q, v);
  VectorX tau(model.nv - 6);
  for (int n = 0; n < 5000; ++n) {
    for (int j = 0; j < tau.size(); ++j) tau[j] = 0.5 * std::sin(20 * sim.time() + j);
    sim.step(tau);
  }
  EXPECT_LT((spatial_momentum(model, data, sim.q(), sim.v()) - h0).norm() / h0.norm(), 1e-8);
  EXPECT_GT(std::abs(kinetic_energy(model, data, sim.q(), sim.v()) - e0) / e0, 1e-3);
}
