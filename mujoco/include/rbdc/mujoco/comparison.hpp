// A sampled run (our simulator or MuJoCo) and the comparison metrics of paper 000 Section 6.3 / 7.
#pragma once

#include <string>
#include <vector>

#include "rbdc/sim/contact.hpp"

namespace rbdc::mujoco {

struct Sample {
  double t = 0;
  VectorX q, v;                       ///< docs/conventions.md layout
  std::vector<sim::FootContact> contacts;  ///< foot order of the model
};
using Trajectory = std::vector<Sample>;

struct ComparisonMetrics {
  Vector3 position_mae_mm = Vector3::Zero();  ///< trunk x, y, z
  Vector3 euler_mae_deg = Vector3::Zero();    ///< roll, pitch, yaw (ZYX angles), wrapped
  double contact_agreement = 0;     ///< fraction of samples with equal activation (one foot)
  double touchdown_shift_ms = 0;    ///< mean |Δt| from each of our touch-downs to MuJoCo's nearest
  int touchdowns_ours = 0, touchdowns_mujoco = 0;
  double normal_force_mae = 0;      ///< N, world-vertical contact force of that foot
  int samples = 0;
};

/// Compares two runs sampled at the same instants (the shorter length is used) on foot `foot`.
ComparisonMetrics compare_trajectories(const Trajectory& ours, const Trajectory& mujoco, int foot);

}  // namespace rbdc::mujoco
