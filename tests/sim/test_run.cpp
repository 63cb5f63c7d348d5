// The run loop (rbdc/sim/run.hpp) with any controller: a zero-order hold at the control period,
// samples at t = 0, every interval and at the end, the stop callback, and measured foot forces
// only for controllers that ask for them.
#include <gtest/gtest.h>

#include <memory>

#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/run.hpp"

using namespace rbdc;
using namespace rbdc::sim;

namespace {

// Zero torques from a pose 1 m above the ground; records what each update was given.
class RecordingController final : public Controller {
 public:
  RecordingController(const Model& model, bool forces)
      : nq_(model.nq), forces_(forces), tau_(VectorX::Zero(model.nv - 6)) {}
  std::string name() const override { return "recording"; }
  std::vector<Parameter> parameters() const override { return {}; }
  VectorX initial_configuration() const override {
    VectorX q = VectorX::Zero(nq_);
    q[2] = 1.0;
    q[3] = 1;  // identity quaternion
    return q;
  }
  bool uses_foot_forces() const override { return forces_; }
  const VectorX& update(const ControllerInput& input) override {
    times.push_back(input.t);
    holds.push_back(input.dt);
    force_columns.push_back(input.foot_forces.cols());
    return tau_;
  }
  std::vector<double> times, holds;
  std::vector<Eigen::Index> force_columns;

 private:
  int nq_;
  bool forces_;
  VectorX tau_;
};

class Run : public ::testing::Test {
 protected:
  Model model = load_robot(default_urdf());
  std::unique_ptr<DynamicsModel> dynamics = make_runtime_dynamics(model);
  Simulator simulator{*dynamics, SimOptions{}};  // dt = 1e-4 s
};

TEST_F(Run, UpdatesAtTheControlPeriodAndHoldsBetween) {
  RecordingController controller(model, false);
  RunOptions options;
  options.duration = 0.01;
  options.control_period = 1e-3;
  options.sample_interval = 0;
  const RunSummary summary = run(simulator, controller, options);
  EXPECT_EQ(summary.steps, 100);
  EXPECT_TRUE(summary.finite);
  EXPECT_EQ(summary.controller_calls, 10);
  ASSERT_EQ(controller.times.size(), 10u);
  for (std::size_t i = 0; i < controller.times.size(); ++i) {
    EXPECT_NEAR(controller.times[i], 1e-3 * static_cast<double>(i), 1e-12);
    EXPECT_NEAR(controller.holds[i], 1e-3, 1e-15);
  }
  EXPECT_NEAR(simulator.time(), 0.01, 1e-12);
  EXPECT_LT(simulator.q()[2], 1.0);  // it fell: the loop did step the plant
}

TEST_F(Run, SamplesFromTheInitialStateToTheEnd) {
  RecordingController controller(model, false);
  RunOptions options;
  options.duration = 0.01;
  options.sample_interval = 2e-3;
  std::vector<double> times;
  VectorX first;
  RunCallbacks callbacks;
  callbacks.sample = [&](Simulator& s) {
    if (times.empty()) first = s.q();
    times.push_back(s.time());
  };
  run(simulator, controller, options, callbacks);
  ASSERT_EQ(times.size(), 6u);  // t = 0, 2, 4, 6, 8, 10 ms
  EXPECT_EQ(times.front(), 0.0);
  EXPECT_NEAR(times.back(), 0.01, 1e-12);
  EXPECT_EQ(first, controller.initial_configuration());
  EXPECT_EQ(controller.times.size(), 100u);  // every step by default
}

TEST_F(Run, StopCallbackEndsTheRunWithItsReason) {
  RecordingController controller(model, false);
  RunOptions options;
  options.duration = 0.01;
  RunCallbacks callbacks;
  callbacks.stop = [](Simulator& s) -> const char* { return s.time() > 0.00495 ? "halfway" : nullptr; };
  const RunSummary summary = run(simulator, controller, options, callbacks);
  EXPECT_EQ(summary.steps, 50);
  ASSERT_NE(summary.stop_reason, nullptr);
  EXPECT_STREQ(summary.stop_reason, "halfway");
}

TEST_F(Run, FootForcesOnlyForControllersThatAsk) {
  RunOptions options;
  options.duration = 1e-3;
  RecordingController blind(model, false), sensing(model, true);
  run(simulator, blind, options);
  run(simulator, sensing, options);
  for (Eigen::Index columns : blind.force_columns) EXPECT_EQ(columns, 0);
  for (Eigen::Index columns : sensing.force_columns)
    EXPECT_EQ(columns, static_cast<Eigen::Index>(model.feet.size()));
}

}  // namespace
