// The 10 s trot of paper 000 Section 6.2 on the generated dynamics.
#include <gtest/gtest.h>

#include "rbdc/control/pd_trot.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/run.hpp"

using namespace rbdc;
using namespace rbdc::sim;
using rbdc::control::GaitParameters;
using rbdc::control::PdGains;
using rbdc::control::PdTrotController;


TEST(Trot, TenSecondsForwardWithoutFallingOrNaN) {
  const Model model = load_robot(default_urdf());
  const auto dynamics = make_generated_dynamics();
  SimOptions options;
  Simulator sim(*dynamics, options);
  PdTrotController controller(model, GaitParameters{}, PdGains{}, options.contact.foot_radius);
  RunOptions run_options;
  run_options.sample_interval = 0;
  const RunSummary summary = run(sim, controller, run_options);
  ASSERT_TRUE(summary.finite);
  EXPECT_EQ(summary.steps, 100000);
  // Trunk box half-height is 0.05 m: its underside stays well above the ground.
  EXPECT_GT(summary.min_trunk_height, 0.15);
  EXPECT_GT(sim.q()[0], 1.0);               // forward, about 0.14 m/s
  EXPECT_LT(std::abs(sim.q()[1]), 0.1);     // and roughly straight
  std::printf("%s dynamics: x = %.3f m, lowest trunk z = %.3f m\n", dynamics->name().c_str(), sim.q()[0],
              summary.min_trunk_height);
}

// The two comparisons below run the trot controller in the air (contact off), where the
// discretisations agree to round-off; the one after them turns contact on.
TEST(Trot, EulerAndQuaternionStatesAgree) {
  const Model model = load_robot(default_urdf());
  const auto dynamics = make_generated_dynamics();
  SimOptions quaternion, euler;
  quaternion.contact_enabled = euler.contact_enabled = false;
  euler.state = StateKind::Euler;
  RunOptions run_options;
  run_options.duration = 0.5;
  run_options.sample_interval = 0;
  Simulator a(*dynamics, quaternion);
  PdTrotController ca(model, GaitParameters{}, PdGains{}, quaternion.contact.foot_radius);
  ASSERT_TRUE(run(a, ca, run_options).finite);
  const auto dynamics_b = make_generated_dynamics();
  Simulator b(*dynamics_b, euler);
  PdTrotController cb(model, GaitParameters{}, PdGains{}, euler.contact.foot_radius);
  ASSERT_TRUE(run(b, cb, run_options).finite);
  EXPECT_GT(a.v().tail(12).norm(), 0.5);  // the legs did move
  EXPECT_LT((a.q() - b.q()).norm(), 1e-6);
  EXPECT_LT((a.v() - b.v()).norm(), 1e-5);
}

// Paper 000 as it runs: ZYX-Euler state (Eqs. 39-42) with Heun, now with Table I's contact on
// (the implicit friction no longer rings in stance): 1 s of trot from rest, two touch-downs per leg.
TEST(Trot, EulerAndQuaternionStatesAgreeWithContact) {
  const Model model = load_robot(default_urdf());
  RunOptions run_options;
  run_options.duration = 1.0;
  run_options.sample_interval = 0;
  std::vector<VectorX> q, v;
  for (StateKind state : {StateKind::Quaternion, StateKind::Euler}) {
    const auto dynamics = make_generated_dynamics();
    SimOptions options;
    options.state = state;
    Simulator sim(*dynamics, options);
    PdTrotController controller(model, GaitParameters{}, PdGains{}, options.contact.foot_radius);
    ASSERT_TRUE(run(sim, controller, run_options).finite);
    q.push_back(sim.q());
    v.push_back(sim.v());
  }
  std::printf("with contact, 1 s: |q_euler - q_quat| = %.2e, |v_euler - v_quat| = %.2e\n", (q[1] - q[0]).norm(),
              (v[1] - v[0]).norm());
  EXPECT_GT(v[0].tail(12).norm(), 0.5);  // the legs move
  // Measured 2.7e-7 and 5.4e-6 (the explicit friction gave differences of the size of the chatter).
  EXPECT_LT((q[1] - q[0]).norm(), 1e-5);
  EXPECT_LT((v[1] - v[0]).norm(), 1e-4);
}

TEST(Trot, IntegratorsAgreeOnAShortRun) {
  const Model model = load_robot(default_urdf());
  RunOptions run_options;
  run_options.duration = 0.3;
  run_options.sample_interval = 0;
  std::vector<VectorX> finals;
  for (Integrator integrator : {Integrator::RK4, Integrator::Heun, Integrator::SemiImplicitEuler}) {
    const auto dynamics = make_generated_dynamics();
    SimOptions options;
    options.integrator = integrator;
    options.contact_enabled = false;
    Simulator sim(*dynamics, options);
    PdTrotController controller(model, GaitParameters{}, PdGains{}, options.contact.foot_radius);
    ASSERT_TRUE(run(sim, controller, run_options).finite);
    finals.push_back(sim.q());
  }
  std::printf("|heun - rk4| = %.2e, |semi-implicit - rk4| = %.2e\n", (finals[1] - finals[0]).norm(),
              (finals[2] - finals[0]).norm());
  EXPECT_LT((finals[1] - finals[0]).norm(), 1e-6);  // second order, dt = 1e-4
  EXPECT_LT((finals[2] - finals[0]).norm(), 1e-3);  // first order
}
