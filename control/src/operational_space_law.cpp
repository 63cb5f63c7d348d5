#include "rbdc/control/operational_space_law.hpp"

#include <Eigen/Cholesky>

#include "rbdc/control/pseudo_inverse.hpp"

namespace rbdc::control {

void operational_space_stance_torques(const TrunkTaskDynamics& dynamics,
                                      const std::array<int, 6>& stance_joints,
                                      const JointTorques& tau_swing, const JointTorques& tau_passive,
                                      const Eigen::Vector2d& attitude_acceleration,
                                      const Vector6& weights, StanceTorques& out) {
  // S_stᵀ picks the stance columns of J̄ᵀ; S_swᵀ τ_sw and S_stᵀ τ_st,p are the torques with the
  // other legs' entries zeroed.
  Matrix6 JbarT_stance;
  Vector6 tau_passive_stance;
  JointTorques tau_swing_only = tau_swing;
  for (int j = 0; j < 6; ++j) {
    JbarT_stance.col(j) = dynamics.JbarT.col(stance_joints[j]);
    tau_passive_stance[j] = tau_passive[stance_joints[j]];
    tau_swing_only[stance_joints[j]] = 0;
  }
  // Eq. 53: passive acceleration with τ_sw = 0 and the passive stance torque.
  const Eigen::LDLT<Matrix6> Lambda_ldlt(dynamics.Lambda);
  out.passive_acceleration = Lambda_ldlt.solve(JbarT_stance * tau_passive_stance - dynamics.b);
  // Eqs. 51-52 for roll and pitch; yaw and the linear components follow the passive dynamics.
  out.desired_acceleration = out.passive_acceleration;
  out.desired_acceleration.head<2>() = attitude_acceleration;
  // Eq. 55: τ_st = (W J̄ᵀ S_stᵀ)† W (Λ ẍ_d + b − J̄ᵀ S_swᵀ τ_sw), σ < σ_max/100 dropped.
  const Matrix6 A = weights.asDiagonal() * JbarT_stance;
  const Vector6 y = weights.asDiagonal() * (dynamics.Lambda * out.desired_acceleration + dynamics.b -
                                            dynamics.JbarT * tau_swing_only);
  const Vector6 tau_stance = truncated_pseudo_inverse_solve<6, 6>(A, y, kSingularValueCutoff, &out.rank);
  out.tau.setZero();
  for (int j = 0; j < 6; ++j) out.tau[stance_joints[j]] = tau_stance[j];
}

}  // namespace rbdc::control
