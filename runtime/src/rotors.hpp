// Geared rotors in the Newton-Euler recursions (docs/runtime.md, "Rotors and armature"): the rotor
// of joint i is a body carried by λ(i) at X_rot, spinning with S_rot = gr · (axis; 0) at rate q̇_i
// (Featherstone, RBDA geared motors; Jain ch. 12; Cheetah-Software's model). It only adds terms:
// a model without rotors never reaches this code.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc::detail {

/// Rotor i's wrench at its origin, rotor coordinates, from its parent's velocity and acceleration
/// (Eqs. 19-20 with X_rot, S_rot in place of X_up, S):
///   v_rot = X_rot v_λ + S_rot q̇_i,  a_rot = X_rot a_λ + S_rot q̈_i + v_rot × S_rot q̇_i,
///   f_rot = I_rot a_rot + v_rot ×* I_rot v_rot
inline Vector6 rotor_wrench(const Model& model, size_t i, const Vector6& v_parent,
                            const Vector6& a_parent, double qd, double qdd) {
  const Vector6& S = model.rotor_subspace[i];
  const Matrix6& I = model.rotor_inertia[i];
  const Vector6 v = model.X_rotor[i] * v_parent + S * qd;
  const Vector6 a = model.X_rotor[i] * a_parent + S * qdd + crm(v) * S * qd;
  return I * a + crf(v) * I * v;
}

/// Rotor i's velocity v_rot = X_rot v_λ + S_rot q̇_i (rotor coordinates).
inline Vector6 rotor_velocity(const Model& model, const Data& data, size_t i, double qd) {
  return model.X_rotor[i] * data.v[static_cast<size_t>(model.parent[i])] + model.rotor_subspace[i] * qd;
}

}  // namespace rbdc::detail
