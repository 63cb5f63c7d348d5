// Operational frames (docs/model.md, "Frames"; conventions in docs/conventions.md, "Frames"): the
// placement, velocity, Jacobian and J̇v of every frame of the model, a body plus a constant pose
// X_i^F. Results are per frame k = index in model.frames. "local": at the frame origin in frame
// axes (Pinocchio's LOCAL); "world": at the frame origin in world axes (LOCAL_WORLD_ALIGNED).
// Spatial vectors are (angular; linear), Featherstone's order. Every function checks its argument
// sizes and throws std::invalid_argument on a mismatch.
#pragma once

#include <string>

#include "rbdc/data.hpp"

namespace rbdc {

/// The index of the frame called `name` in model.frames; throws std::invalid_argument naming it and
/// the model when there is none.
int frame_index(const Model& model, const std::string& name);

/// Placements: data.world_R_frame[k] = R_F^W = R_i^W (R_i^F)ᵀ and column k of the returned matrix
/// = p_F = p_i + R_i^W r_F (the frame origin in the world; Eqs. 15-18 with X_i^F in place of
/// X_i^fk). q: nq. Returns data.frame_position (3 × n_frames).
const Matrix3X& frame_placements(const Model& model, Data& data, const VectorRef& q);

/// Velocities (Eq. 13 moved to the frame): v_F = X_i^F v_i (local, data.frame_velocity_local) and
/// diag(R_F^W, R_F^W) v_F (world-aligned, data.frame_velocity_world); 6 × n_frames each.
/// q: nq, v: nv. Returns data.frame_velocity_world.
const Matrix6X& frame_velocities(const Model& model, Data& data, const VectorRef& q, const VectorRef& v);

/// Jacobians (Eq. B3 moved to the frame): J_F = X_i^F [X_j^i S_j]_{j ∈ κ(i)} (local, 6 × nv each in
/// data.frame_jacobian_local) and diag(R_F^W, R_F^W) J_F (data.frame_jacobian_world), so that
/// J v = the frame velocities above. q: nq. Returns data.frame_jacobian_world.
const std::vector<Matrix6X>& frame_jacobians(const Model& model, Data& data, const VectorRef& q);

/// J̇v, the frame's acceleration at a = 0 (a floating base's classical trunk acceleration zero, as
/// feet_bias_accelerations): spatial a_F = X_i^F a_i with a_i of Eq. 19 (data.frame_bias_spatial,
/// local axes: J̇_local v, Pinocchio's getFrameAcceleration(LOCAL)), and classical
/// diag(R, R)(ω̇_F; a_F,lin + ω_F × v_F) (data.frame_bias_classical, world axes: J̇_world v,
/// Pinocchio's getFrameClassicalAcceleration(LOCAL_WORLD_ALIGNED)); 6 × n_frames each.
/// q: nq, v: nv. Returns data.frame_bias_classical.
const Matrix6X& frame_bias_accelerations(const Model& model, Data& data, const VectorRef& q,
                                         const VectorRef& v);

}  // namespace rbdc
