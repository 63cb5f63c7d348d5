// The operational-space controller keeps the Mini Cheetah trotting (2 s at 1 m/s, generated
// dynamics) with roll and pitch held during stance.
#include <gtest/gtest.h>

#include "rbdc/control/trot_experiment.hpp"
#include "rbdc/sim/robot.hpp"

namespace {

using namespace rbdc;
using namespace rbdc::control;

TEST(OscTrot, TwoSecondsWithoutFalling) {
  const Model model = sim::load_robot(sim::default_urdf());
  std::unique_ptr<sim::DynamicsModel> dynamics = sim::make_generated_dynamics();
  if (!dynamics) dynamics = sim::make_runtime_dynamics(model);
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

}  // namespace
