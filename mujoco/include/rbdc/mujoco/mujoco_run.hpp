// The trot of our controller driving MuJoCo (paper 000 Section 6.3): same robot (MJCF from the
// model), same trajectory generator and PD law, MuJoCo's own contact and integrator.
#pragma once

#include "rbdc/mjcf/mjcf_writer.hpp"
#include "rbdc/sim/trajectory.hpp"
#include "rbdc/sim/trot.hpp"
#include "rbdc/sim/trot_run.hpp"

namespace rbdc::sim {

struct MujocoRun {
  Trajectory trajectory;
  double wall_seconds = 0;  ///< mj_step + control, sampling excluded
  long steps = 0;
};

/// Runs MuJoCo model `m` (compiled from `model` by load_mjmodel) from `controller`'s standing
/// configuration for options.duration, sampling every options.sample_interval.
MujocoRun run_mujoco_trot(const Model& model, const mjModel* m, TrotController& controller,
                          const RunOptions& options);

/// The state of MuJoCo data `d` in our layout: q = (p_W, quaternion, joints), v = (ω_B, v_B, q̇).
void mujoco_state(const Model& model, const mjcf::MujocoIndex& index, const mjData* d, VectorX& q,
                  VectorX& v);

/// Contact of each foot in MuJoCo: active when a contact on its sphere pushes, force in world
/// coordinates (the force the ground applies to the foot).
std::vector<FootContact> mujoco_contacts(const mjModel* m, const mjData* d, const mjcf::MujocoIndex& index);

}  // namespace rbdc::sim
