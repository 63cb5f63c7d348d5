// The stance torques of paper 001 Section 5.1 (Eqs. 49-55). Given the trunk task dynamics
// (closed chain Eq. 48 or open chain Eq. 28), the swing torques already chosen and the passive
// stance torques, the stance torques realise, in the weighted least-squares sense,
//   Λ ẍ_d + b = J̄ᵀ S_swᵀ τ_sw + J̄ᵀ S_stᵀ τ_st                                   (Eq. 49 / 50)
// with ẍ_d = the passive acceleration (Eq. 53) except roll and pitch, set by Eqs. 51-52.
#pragma once

#include <array>

#include "rbdc/control/mini_cheetah.hpp"

namespace rbdc::control {

/// Eq. 54: W = diag(w_ωx, w_ωy, w_ωz, w_vx, w_vy, w_vz); the paper's Fig. 9 values by default.
inline Vector6 default_task_weights() { return (Vector6() << 10, 10, 1, 1, 1, 1).finished(); }

struct StanceTorques {
  Vector6 passive_acceleration = Vector6::Zero();  ///< Eq. 53
  Vector6 desired_acceleration = Vector6::Zero();  ///< ẍ_d
  JointTorques tau = JointTorques::Zero();         ///< τ_st on the stance joints, 0 elsewhere
  int rank = 0;                                    ///< singular values kept in Eq. 55
};

/// stance_joints: the 6 joint indices (0 … 11) of the two stance legs. tau_swing: τ_sw on the
/// swing joints (stance entries ignored). tau_passive: τ_st,p on the stance joints (swing
/// entries ignored). attitude_acceleration: (ω̇_x, ω̇_y) desired by Eqs. 51-52.
void operational_space_stance_torques(const TrunkTaskDynamics& dynamics,
                                      const std::array<int, 6>& stance_joints,
                                      const JointTorques& tau_swing, const JointTorques& tau_passive,
                                      const Eigen::Vector2d& attitude_acceleration,
                                      const Vector6& weights, StanceTorques& out);

}  // namespace rbdc::control
