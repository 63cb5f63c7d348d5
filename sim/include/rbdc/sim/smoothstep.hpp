// The cubic smoothstep used by the contact model of paper 000 (damping ramp, Eq. 35; friction, Eq. 38).
#pragma once

namespace rbdc::sim {

/// 0 below `edge0`, 1 above `edge1`, 3s² − 2s³ in between (s the position in [edge0, edge1]);
/// continuous with a continuous first derivative.
inline double smoothstep(double edge0, double edge1, double x) {
  const double s = (x - edge0) / (edge1 - edge0);
  if (s <= 0) return 0;
  if (s >= 1) return 1;
  return s * s * (3 - 2 * s);
}

}  // namespace rbdc::sim
