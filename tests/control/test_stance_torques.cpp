// Standing on four feet, the stance torques of Eqs. 53-55 computed from the generated closed-chain
// recursion realise the desired trunk acceleration: checked through the exactly constrained
// forward dynamics of the runtime (H a − J_cᵀ f = Sᵀτ − C − G, J_c a = −J̇_c v).
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "mini_cheetah/stance_osc.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/control/operational_space_law.hpp"
#include "rbdc/control/osc_trot.hpp"
#include "rbdc/control/trunk_dynamics.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/sim/robot.hpp"

namespace {

using namespace rbdc;
using namespace rbdc::control;

// Trunk acceleration a[0:6] of the constrained dynamics with every foot pinned.
Vector6 constrained_trunk_acceleration(const Model& model, const VectorX& q, const VectorX& v,
                                       const JointTorques& tau) {
  Data data(model);
  const int nv = model.nv, nc = 3 * static_cast<int>(model.feet.size());
  const MatrixX M = mass_matrix(model, data, q);
  const VectorX c = quadratic_velocity_terms(model, data, q, v);
  const VectorX g = gravity_terms(model, data, q);
  const MatrixX J = feet_jacobian(model, data, q);
  const Matrix3X Jdot_v = feet_bias_accelerations(model, data, q, v);
  MatrixX K = MatrixX::Zero(nv + nc, nv + nc);
  K.topLeftCorner(nv, nv) = M;
  K.topRightCorner(nv, nc) = -J.transpose();
  K.bottomLeftCorner(nc, nv) = J;
  VectorX rhs(nv + nc);
  rhs.head(nv) = -c - g;
  rhs.segment(6, kJoints) += tau;
  rhs.tail(nc) = -Eigen::Map<const VectorX>(Jdot_v.data(), nc);
  return K.partialPivLu().solve(rhs).head<6>();
}

class StanceTorquesTest : public ::testing::Test {
 protected:
  StanceTorquesTest() : model_(sim::load_robot(sim::default_urdf())) {
    OscTrotController controller(model_, TrotParameters{}, StanceControl::OperationalSpace, 0.02);
    q_ = controller.initial_configuration();
    q_[7] = 0.05, q_[11] = -0.04, q_[16] = 0.03;  // not quite symmetric
    v_ = VectorX::Zero(kNv);  // at rest: the recursion assumes feet at rest (Eq. 16)
  }
  Model model_;
  VectorX q_, v_;
};

TEST_F(StanceTorquesTest, FourFootStanceRealisesTheDesiredTrunkAcceleration) {
  // Four feet pinned: the recursion of the stance_osc scene (Table 2, all feet in contact).
  TrunkTaskDynamics dynamics;
  const double ground_mass = mini_cheetah_ground_mass();
  rbdc_gen::mini_cheetah::stance_osc::osc_closed_chain<double>(
      q_.data(), v_.data(), &ground_mass, dynamics.Lambda.data(), dynamics.JbarT.data(), dynamics.b.data());
  std::array<int, kJoints> all_joints;
  for (int j = 0; j < kJoints; ++j) all_joints[j] = j;
  JointTorques tau_passive = JointTorques::Zero();
  tau_passive[2] = tau_passive[5] = tau_passive[8] = tau_passive[11] = -3.0;  // knees push
  const Eigen::Vector2d attitude_acceleration(2.0, -1.5);  // rad/s², roll and pitch
  StanceTorques out;
  operational_space_stance_torques<kJoints>(dynamics, all_joints, JointTorques::Zero(), tau_passive,
                                            attitude_acceleration, default_task_weights(), out);
  EXPECT_EQ(out.rank, 6);  // four feet: every trunk direction is actuated
  EXPECT_DOUBLE_EQ(out.desired_acceleration[0], 2.0);
  EXPECT_DOUBLE_EQ(out.desired_acceleration[1], -1.5);
  EXPECT_TRUE(out.desired_acceleration.tail<4>() == out.passive_acceleration.tail<4>());
  // The exactly constrained dynamics under these torques give the desired trunk acceleration.
  const Vector6 a = constrained_trunk_acceleration(model_, q_, v_, out.tau);
  EXPECT_LT((a - out.desired_acceleration).norm(), 1e-4 * (1 + out.desired_acceleration.norm()))
      << "achieved " << a.transpose() << "\ndesired  " << out.desired_acceleration.transpose();
  // And the passive torques alone give the passive acceleration (Eq. 53).
  const Vector6 a_passive = constrained_trunk_acceleration(model_, q_, v_, tau_passive);
  EXPECT_LT((a_passive - out.passive_acceleration).norm(), 1e-4 * (1 + a_passive.norm()));
}

TEST_F(StanceTorquesTest, TwoFootStanceIsRankDeficientAndDropsTheDiagonalMoment) {
  TrunkTaskDynamics dynamics;
  closed_chain_dynamics(q_.data(), v_.data(), StancePair::LfRh, mini_cheetah_ground_mass(), dynamics);
  StanceTorques out;
  operational_space_stance_torques<6>(dynamics, {0, 1, 2, 9, 10, 11}, JointTorques::Zero(),
                                      JointTorques::Zero(), Eigen::Vector2d(1, 1),
                                      default_task_weights(), out);
  // Point feet cannot make a moment about the line through them (paper 001 Sec. 5.1).
  EXPECT_EQ(out.rank, 5);
  // Only the stance legs (LF, RH) get torques.
  EXPECT_TRUE(out.tau.segment<6>(3).isZero(0.0));
  EXPECT_GT(out.tau.head<3>().norm(), 0);
}

}  // namespace
