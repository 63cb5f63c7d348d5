// Any controller (rbdc::sim::Controller) driving MuJoCo (paper 000 Section 6.3): the same robot
// (MJCF from the model), MuJoCo's own contact and integrator, our state layout on both sides.
#pragma once

#include "rbdc/mjcf/mjcf_writer.hpp"
#include "rbdc/mujoco/comparison.hpp"
#include "rbdc/sim/controller.hpp"
#include "rbdc/sim/run.hpp"

namespace rbdc::mujoco {

struct MujocoRun {
  Trajectory trajectory;
  double wall_seconds = 0;  ///< mj_step + control, sampling excluded
  long steps = 0;
};

/// Runs MuJoCo model `m` (compiled from `model` by load_mjmodel) from `controller`'s initial
/// configuration for options.duration, updating the controller every step and sampling every
/// options.sample_interval (control_period is not used: MuJoCo's step is the control period).
MujocoRun run_mujoco(const Model& model, const mjModel* m, sim::Controller& controller,
                     const sim::RunOptions& options);

/// The state of MuJoCo data `d` in our layout: q = (p_W, quaternion, joints), v = (ω_B, v_B, q̇).
void mujoco_state(const Model& model, const mjcf::MujocoIndex& index, const mjData* d, VectorX& q,
                  VectorX& v);

/// Contact of each foot in MuJoCo: active when a contact on its sphere pushes, force in world
/// coordinates (the force the ground applies to the foot).
std::vector<sim::FootContact> mujoco_contacts(const mjModel* m, const mjData* d,
                                              const mjcf::MujocoIndex& index);

}  // namespace rbdc::mujoco
