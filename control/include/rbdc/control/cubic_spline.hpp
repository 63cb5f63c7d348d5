// Cubic set-point trajectories for trunk roll and pitch (paper 001 Eqs. 51-52: "γ_d, β_d, γ̇_d,
// β̇_d are computed from cubic spline trajectories"): one Hermite segment from the state at the
// start of stance to a target angle with zero rate, then held.
#pragma once

namespace rbdc::control {

struct SetPoint {
  double angle = 0;  ///< rad
  double rate = 0;   ///< rad/s
};

class CubicSetPoint {
 public:
  CubicSetPoint() = default;
  /// Starts at (angle0, rate0) at time t0 and reaches (target, 0) at t1 > t0 (clamped to
  /// t0 + 1 ms when closer, so the cubic stays finite).
  CubicSetPoint(double t0, double angle0, double rate0, double t1, double target);
  /// Desired angle and rate at time t (held at the ends outside [t0, t1]).
  SetPoint at(double t) const;

 private:
  double t0_ = 0, duration_ = 1, a0_ = 0, a1_ = 0, a2_ = 0, a3_ = 0;
};

}  // namespace rbdc::control
