// Trunk roll γ and pitch β (rotations about the trunk x and y axes, paper 001 Sec. 5.1) measured
// from the state, and the PD law shared by Eqs. 51-52 (desired angular accelerations) and
// Eqs. 56-57 (hip torques): u = k (θ_d − θ) + k_d (θ̇_d − θ̇).
#pragma once

#include "rbdc/control/cubic_spline.hpp"
#include "rbdc/spatial.hpp"

namespace rbdc::control {

struct TrunkAttitude {
  double roll = 0, pitch = 0, yaw = 0;  ///< ZYX Euler angles, rad
  double roll_rate = 0, pitch_rate = 0; ///< rad/s
};

/// Attitude from q = (p, quaternion w x y z, …) and v = (ω_B, …) (docs/conventions.md); the rates
/// are the ZYX Euler rates (paper 000 Eq. 42).
TrunkAttitude trunk_attitude(const double* q, const double* v);

struct AttitudeGains {
  double roll_kp = 0, roll_kd = 0;    ///< k_γ, k_γ̇
  double pitch_kp = 0, pitch_kd = 0;  ///< k_β, k_β̇
};

/// (u_roll, u_pitch) of Eqs. 51-52 (or 56-57): PD of the measured attitude toward the set-points.
Eigen::Vector2d attitude_pd(const AttitudeGains& gains, const TrunkAttitude& measured,
                            const SetPoint& roll_desired, const SetPoint& pitch_desired);

}  // namespace rbdc::control
