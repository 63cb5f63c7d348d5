// Tree kinematics (paper 000 Section 3): body transforms and velocities (Alg. 1), world transforms
// (Eqs. 14-15), foot positions, orientations and velocities (Eqs. 16-18, 37).
// Every function checks its argument sizes and throws std::invalid_argument on a mismatch.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// Alg. 1 without velocities (Eqs. 9-12) plus the trunk's world transform (Eq. 14).
/// q: nq. Fills data.X_up, data.X_root, data.X_world[0]. The quaternion of a floating base is
/// normalised before use; a fixed base sits at the world origin (X_W^0 = 1).
void kinematics(const Model& model, Data& data, const VectorRef& q);

/// Alg. 1 (Eqs. 9-13) plus Eq. 14. q: nq, v: nv. Also fills data.v (v_0 = v[0:6] for a floating
/// base, zero for a fixed one).
void kinematics(const Model& model, Data& data, const VectorRef& q, const VectorRef& v);

/// Eq. 15: X_W^i = X_0^i X_W^0 for every body. q: nq. Returns data.X_world.
const std::vector<Matrix6>& world_transforms(const Model& model, Data& data, const VectorRef& q);

/// Eqs. 16-18: world position of every foot (3 × n_feet) and its orientation (data.world_R_foot,
/// the foot frame has its body's orientation). q: nq. Returns data.feet_position.
const Matrix3X& feet_positions(const Model& model, Data& data, const VectorRef& q);

/// Eq. 37: world-frame linear velocity of every foot point (3 × n_feet). q: nq, v: nv.
/// Returns data.feet_velocity.
const Matrix3X& feet_velocities(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v);

/// J̇ v: the world-frame classical acceleration of every foot point when a = 0 (3 × n_feet),
/// from the velocity-product accelerations of Eq. 19. q: nq, v: nv.
/// Returns data.feet_bias_acceleration.
const Matrix3X& feet_bias_accelerations(const Model& model, Data& data, const VectorRef& q,
                                        const VectorRef& v);

}  // namespace rbdc
