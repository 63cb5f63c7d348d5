// Foot placement and swing: a Raibert-style heuristic (Raibert 1986; paper 001 Sec. 5) picks the
// touch-down point from the trunk velocity, and a smooth swing curve leads the foot there.
#pragma once

#include "rbdc/spatial.hpp"

namespace rbdc::control {

/// Touch-down point (world, on the ground plane z = ground_z) for a foot whose hip is at
/// hip_at_touchdown when it lands: half a stance of travel ahead of the hip plus a correction
/// proportional to the velocity error, p = hip + v T_st / 2 + k_v (v − v_d) (horizontal parts).
Vector3 raibert_touchdown(const Vector3& hip_at_touchdown, const Vector3& velocity,
                          const Vector3& desired_velocity, double stance_duration,
                          double velocity_gain, double ground_z);

struct SwingPoint {
  Vector3 position = Vector3::Zero();
  Vector3 velocity = Vector3::Zero();
};

/// Swing curve from lift-off to touch-down over `duration` at time s·duration (s ∈ [0, 1]):
/// horizontal smoothstep blend, vertical raised cosine of the given apex height; the velocity
/// treats the end points as fixed.
SwingPoint swing_point(const Vector3& liftoff, const Vector3& touchdown, double height,
                       double duration, double s);

}  // namespace rbdc::control
