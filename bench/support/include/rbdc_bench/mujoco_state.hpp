// The same robot and state in MuJoCo: the model goes through the MJCF writer (rbdc_mjcf), and states
// are converted between the coordinates of docs/conventions.md and MuJoCo's. Only MuJoCo's free joint
// differs: its velocity is (linear velocity of the trunk origin in WORLD coordinates, angular velocity
// in trunk coordinates), ours is (ω_B, v_B) both in trunk coordinates. With R = R_0^W,
//   v_mj = T v,  T = [0 R; 1 0] on the trunk block and 1 on the joints,
// and accelerations map the same way (ours is the classical trunk acceleration), so by power
// equivalence τ = Tᵀ τ_mj, M = Tᵀ M_mj T and c + g = Tᵀ qfrc_bias.
#pragma once

#include "rbdc/data.hpp"
#include "rbdc/mjcf/mjcf_writer.hpp"

namespace rbdc_bench {

struct MujocoRobot {
  rbdc::Model model;  ///< the rbdc model with MuJoCo's compiled inertias adopted (for comparisons)
  rbdc::mjcf::MjModelPtr m;
  rbdc::mjcf::MjDataPtr d;
  rbdc::mjcf::MujocoIndex index;
};

/// Compiles `model` for MuJoCo with contacts and constraints disabled (pure rigid-body dynamics).
MujocoRobot make_mujoco_robot(const rbdc::Model& model);

/// Writes q (and v, a when given) into d->qpos, d->qvel, d->qacc.
void set_mujoco_state(const MujocoRobot& robot, mjData* d, const rbdc::VectorX& q,
                      const rbdc::VectorX* v = nullptr, const rbdc::VectorX* a = nullptr);

/// T with v_mj = T v at configuration q (nv_mj × nv).
rbdc::MatrixX mujoco_velocity_map(const MujocoRobot& robot, const rbdc::VectorX& q);

/// MuJoCo's joint-space inertia M_mj (full, from mj_crb + mj_fullM) at q, in our coordinates.
rbdc::MatrixX mujoco_mass_matrix(const MujocoRobot& robot, const rbdc::VectorX& q);

/// MuJoCo's bias c + g (mj_rne without acceleration) at (q, v), in our coordinates.
rbdc::VectorX mujoco_bias(const MujocoRobot& robot, const rbdc::VectorX& q, const rbdc::VectorX& v);

}  // namespace rbdc_bench
