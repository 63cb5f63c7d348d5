// The PD trot of paper 000 behind the controller interface: its name and parameters, a hold of
// input.dt advancing its pattern generator, and a start with the feet on the ground.
#include <gtest/gtest.h>

#include "rbdc/control/pd_trot.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/sim/robot.hpp"

using namespace rbdc;
using namespace rbdc::control;

namespace {

double parameter(const sim::Controller& controller, const std::string& name) {
  for (const sim::Parameter& p : controller.parameters())
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

class PdTrot : public ::testing::Test {
 protected:
  Model model = sim::load_robot(sim::default_urdf());
  GaitParameters gait;
  PdGains gains{55, 2};
  const double foot_radius = 0.02;
};

TEST_F(PdTrot, NamesItselfAndItsParameters) {
  gait.period = 0.3;
  const PdTrotController controller(model, gait, gains, foot_radius);
  EXPECT_EQ(controller.name(), "pd-trot");
  EXPECT_EQ(parameter(controller, "period"), 0.3);
  EXPECT_EQ(parameter(controller, "kp"), 55);
  EXPECT_EQ(parameter(controller, "kd"), 2);
  EXPECT_FALSE(controller.uses_foot_forces());
}

TEST_F(PdTrot, OneUpdateHeldTwiceAsLongEqualsTwoUpdates) {
  PdTrotController once(model, gait, gains, foot_radius), twice(model, gait, gains, foot_radius);
  const VectorX q = once.initial_configuration();
  const VectorX v = VectorX::Zero(model.nv);
  const Matrix3X none;
  const double dt = 0.1;
  twice.update({0, dt, q, v, none});
  twice.update({dt, dt, q, v, none});
  const VectorX& tau = once.update({0, 2 * dt, q, v, none});
  // Locked trot phases advance at the same rate, so only round-off separates the two.
  EXPECT_LT((once.desired() - twice.desired()).norm(), 1e-12);
  EXPECT_GT((once.desired() - q.tail(12)).norm(), 1e-3);  // and the targets did move
  EXPECT_EQ(tau.size(), model.nv - 6);
}

TEST_F(PdTrot, StartsStandingWithTheFeetOnTheGround) {
  const PdTrotController controller(model, gait, gains, foot_radius);
  Data data(model);
  const Matrix3X& feet = feet_positions(model, data, controller.initial_configuration());
  for (Eigen::Index k = 0; k < feet.cols(); ++k) EXPECT_NEAR(feet(2, k), foot_radius, 1e-9) << "foot " << k;
}

}  // namespace
