#include "rbdc/control/attitude.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace rbdc::control {

TrunkAttitude trunk_attitude(const double* q, const double* v) {
  const Eigen::Quaterniond quaternion(q[3], q[4], q[5], q[6]);
  const Matrix3 W_R_B = quaternion.normalized().toRotationMatrix();
  TrunkAttitude a;
  // ZYX: W_R_B = Rz(ψ) Ry(θ) Rx(φ).
  a.pitch = std::asin(std::clamp(-W_R_B(2, 0), -1.0, 1.0));
  a.roll = std::atan2(W_R_B(2, 1), W_R_B(2, 2));
  a.yaw = std::atan2(W_R_B(1, 0), W_R_B(0, 0));
  // Euler rates from the body angular velocity: φ̇ = ω_x + (ω_y sin φ + ω_z cos φ) tan θ,
  // θ̇ = ω_y cos φ − ω_z sin φ.
  const double wx = v[0], wy = v[1], wz = v[2];
  const double s = std::sin(a.roll), c = std::cos(a.roll);
  a.roll_rate = wx + (wy * s + wz * c) * std::tan(a.pitch);
  a.pitch_rate = wy * c - wz * s;
  return a;
}

Eigen::Vector2d attitude_pd(const AttitudeGains& gains, const TrunkAttitude& measured,
                            const SetPoint& roll_desired, const SetPoint& pitch_desired) {
  return {gains.roll_kp * (roll_desired.angle - measured.roll) +
              gains.roll_kd * (roll_desired.rate - measured.roll_rate),    // Eq. 51 / 56
          gains.pitch_kp * (pitch_desired.angle - measured.pitch) +
              gains.pitch_kd * (pitch_desired.rate - measured.pitch_rate)};  // Eq. 52 / 57
}

}  // namespace rbdc::control
