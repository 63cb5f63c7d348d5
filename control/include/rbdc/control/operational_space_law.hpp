// The stance torques of paper 001 Section 5.1 (Eqs. 49-55). Given the trunk task dynamics
// (closed chain Eq. 48 or open chain Eq. 28), the swing torques already chosen and the passive
// stance torques, the stance torques realise, in the weighted least-squares sense,
//   Λ ẍ_d + b = J̄ᵀ S_swᵀ τ_sw + J̄ᵀ S_stᵀ τ_st                                   (Eq. 49 / 50)
// with ẍ_d = the passive acceleration (Eq. 53) except roll and pitch, set by Eqs. 51-52.
// Templated on the number of stance joints N (6 in a trot, 12 when standing on four feet).
#pragma once

#include <array>

#include <Eigen/Cholesky>

#include "rbdc/control/mini_cheetah.hpp"
#include "rbdc/control/pseudo_inverse.hpp"

namespace rbdc::control {

/// Eq. 54: W = diag(w_ωx, w_ωy, w_ωz, w_vx, w_vy, w_vz); the paper's Fig. 9 values by default.
inline Vector6 default_task_weights() { return (Vector6() << 10, 10, 1, 1, 1, 1).finished(); }

struct StanceTorques {
  Vector6 passive_acceleration = Vector6::Zero();  ///< Eq. 53
  Vector6 desired_acceleration = Vector6::Zero();  ///< ẍ_d
  JointTorques tau = JointTorques::Zero();         ///< τ_st on the stance joints, 0 elsewhere
  int rank = 0;                                    ///< singular values kept in Eq. 55
};

/// stance_joints: the N joint indices (0 … 11) of the stance legs. tau_swing: τ_sw on the swing
/// joints (stance entries ignored). tau_passive: τ_st,p on the stance joints (swing entries
/// ignored). attitude_acceleration: (ω̇_x, ω̇_y) desired by Eqs. 51-52.
template <int N>
void operational_space_stance_torques(const TrunkTaskDynamics& dynamics,
                                      const std::array<int, N>& stance_joints,
                                      const JointTorques& tau_swing, const JointTorques& tau_passive,
                                      const Eigen::Vector2d& attitude_acceleration,
                                      const Vector6& weights, StanceTorques& out) {
  // S_stᵀ picks the stance columns of J̄ᵀ; S_swᵀ τ_sw and S_stᵀ τ_st,p are the torques with the
  // other legs' entries zeroed.
  Eigen::Matrix<double, 6, N> JbarT_stance;
  Eigen::Matrix<double, N, 1> tau_passive_stance;
  JointTorques tau_swing_only = tau_swing;
  for (int j = 0; j < N; ++j) {
    JbarT_stance.col(j) = dynamics.JbarT.col(stance_joints[j]);
    tau_passive_stance[j] = tau_passive[stance_joints[j]];
    tau_swing_only[stance_joints[j]] = 0;
  }
  // Eq. 53: passive acceleration with τ_sw = 0 and the passive stance torque.
  const Eigen::LDLT<Matrix6> Lambda_ldlt(dynamics.Lambda);
  out.passive_acceleration = Lambda_ldlt.solve(JbarT_stance * tau_passive_stance - dynamics.b);
  // Eqs. 51-52 for roll and pitch; yaw and the linear components follow the passive dynamics.
  out.desired_acceleration = out.passive_acceleration;
  out.desired_acceleration.template head<2>() = attitude_acceleration;
  // Eq. 55: τ_st = (W J̄ᵀ S_stᵀ)† W (Λ ẍ_d + b − J̄ᵀ S_swᵀ τ_sw), σ < σ_max/100 dropped.
  const Eigen::Matrix<double, 6, N> A = weights.asDiagonal() * JbarT_stance;
  const Vector6 y = weights.asDiagonal() * (dynamics.Lambda * out.desired_acceleration + dynamics.b -
                                            dynamics.JbarT * tau_swing_only);
  const Eigen::Matrix<double, N, 1> tau_stance =
      truncated_pseudo_inverse_solve<6, N>(A, y, kSingularValueCutoff, &out.rank);
  out.tau.setZero();
  for (int j = 0; j < N; ++j) out.tau[stance_joints[j]] = tau_stance[j];
}

}  // namespace rbdc::control
