// The operational-space controller keeps the Mini Cheetah trotting (2 s at 1 m/s, generated
// dynamics) with roll and pitch held during stance; its controller interface (name, parameters,
// measured forces for the open chain only).
#include <gtest/gtest.h>

#include "rbdc/control/trot_experiment.hpp"
#include "rbdc/sim/robot.hpp"

namespace {

using namespace rbdc;
using namespace rbdc::control;

TEST(OscTrot, TwoSecondsWithoutFalling) {
  const Model model = sim::load_robot(sim::default_urdf());
  std::unique_ptr<sim::DynamicsModel> dynamics = sim::make_generated_dynamics();
  ExperimentOptions options;
  options.duration = 2.0;
  options.control = StanceControl::OperationalSpace;
  const ExperimentResult result = run_trot_experiment(model, *dynamics, options);
  EXPECT_FALSE(result.fell) << result.fall_reason << " at " << result.fall_time << " s";
  EXPECT_NEAR(result.simulated, 2.0, 1e-6);
  EXPECT_GT(result.roll_error.count, 1000);  // stance control ran most of the time
  EXPECT_LT(result.roll_error.max, 2.0);     // deg
  EXPECT_LT(result.pitch_error.max, 2.0);    // deg
  EXPECT_GT(result.mean_speed, 0.5);         // m/s, over the second second (speed ramp)
}

TEST(OscTrot, NamedParametersSetRollAndPitchAlike) {
  TrotParameters p;
  set_parameter(p, "osc_kp", 500);
  set_parameter(p, "step_duration", 0.2);
  EXPECT_EQ(p.osc_gains.roll_kp, 500);
  EXPECT_EQ(p.osc_gains.pitch_kp, 500);
  EXPECT_EQ(p.step_duration, 0.2);
  EXPECT_THROW(set_parameter(p, "no_such_gain", 1), std::invalid_argument);

  const Model model = sim::load_robot(sim::default_urdf());
  const OscTrotController controller(model, p, StanceControl::HipTorque, 0.02);
  EXPECT_EQ(controller.name(), "raibert");
  bool found = false;
  for (const sim::Parameter& parameter : controller.parameters())
    if (parameter.name == "osc_kp") found = parameter.value == 500;
  EXPECT_TRUE(found);
}

TEST(OscTrot, OnlyTheOpenChainReadsMeasuredForces) {
  const Model model = sim::load_robot(sim::default_urdf());
  OscTrotController closed(model, TrotParameters{}, StanceControl::OperationalSpace, 0.02);
  OscTrotController open(model, TrotParameters{}, StanceControl::OperationalSpaceOpenChain, 0.02);
  EXPECT_FALSE(closed.uses_foot_forces());
  EXPECT_TRUE(open.uses_foot_forces());
  const VectorX q = closed.initial_configuration(), v = VectorX::Zero(kNv);
  const Matrix3X none;
  EXPECT_EQ(closed.update({0, 1e-4, q, v, none}).size(), kJoints);
  EXPECT_THROW(open.update({0, 1e-4, q, v, none}), std::invalid_argument);
}

}  // namespace
