#include "rbdc/control/footstep.hpp"

#include <algorithm>
#include <cmath>

namespace rbdc::control {

Vector3 raibert_touchdown(const Vector3& hip_at_touchdown, const Vector3& velocity,
                          const Vector3& desired_velocity, double stance_duration,
                          double velocity_gain, double ground_z) {
  Vector3 p = hip_at_touchdown;
  p.head<2>() += 0.5 * stance_duration * velocity.head<2>() +
                 velocity_gain * (velocity.head<2>() - desired_velocity.head<2>());
  p.z() = ground_z;
  return p;
}

SwingPoint swing_point(const Vector3& liftoff, const Vector3& touchdown, double height,
                       double duration, double s) {
  s = std::clamp(s, 0.0, 1.0);
  const double blend = s * s * (3 - 2 * s), blend_rate = 6 * s * (1 - s) / duration;
  SwingPoint p;
  p.position = liftoff + blend * (touchdown - liftoff);
  p.velocity = blend_rate * (touchdown - liftoff);
  p.position.z() += 0.5 * height * (1 - std::cos(2 * M_PI * s));
  p.velocity.z() += M_PI * height * std::sin(2 * M_PI * s) / duration;
  return p;
}

}  // namespace rbdc::control
