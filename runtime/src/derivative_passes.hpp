// The tangent (directional-derivative) passes shared by the derivative algorithms: forward-mode
// differentiation of the recursions of paper 000, written out by hand. One pass pushes one
// direction (δq, δv) = (derivatives.direction_q, derivatives.direction_v) through the tree, reading
// the primal quantities that the matching primal call left in Data. Equations: docs/runtime.md,
// "Derivatives".
#pragma once

#include <stdexcept>
#include <string>

#include "rbdc/derivatives.hpp"

namespace rbdc::detail {

inline void check_derivative_data(const char* function, const Model& model,
                                  const DerivativeData& derivatives) {
  if (static_cast<int>(derivatives.dv_body.size()) != model.nb ||
      derivatives.dtau_dq.rows() != model.nv ||
      derivatives.dpdot_dq.rows() != 3 * static_cast<Eigen::Index>(model.feet.size())) {
    throw std::invalid_argument(std::string("rbdc::") + function +
                                ": derivative data was built for a different model than '" +
                                model.name + "'");
  }
}

/// δq_i, δv_i: the direction's entries for joint i ≥ 1.
inline double joint_entry(const Model& model, const VectorRef& direction, size_t i) {
  return direction[model.joints[i].v_index];
}

/// ψ_i, the configuration tangent as a twist of body i in body coordinates (R_i' = R_i exp(ψ̃_ang),
/// the origin moves by ψ_lin). It follows the velocity recursion (Eq. 13) with δq for q̇:
///   ψ_0 = δq[0:6] (floating base) or 0;  ψ_i = X_λ(i)^i ψ_λ(i) + S_i δq_i
inline void tangent_motion_pass(const Model& model, const Data& data, DerivativeData& d) {
  d.dX_motion[0] = model.floating_base ? Vector6(d.direction_q.head<6>()) : Vector6::Zero();
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    d.dX_motion[ui] = data.X_up[ui] * d.dX_motion[j] +
                      model.motion_subspace[ui] * joint_entry(model, d.direction_q, ui);
  }
}

/// δv_i, the tangent of Eq. 13 (v_i = X_λ(i)^i v_λ(i) + S_i q̇_i) with δX_λ(i)^i = −δq_i (S_i×) X_λ(i)^i:
///   δv_0 = δv[0:6] (floating base) or 0
///   δv_i = X_λ(i)^i δv_λ(i) − δq_i (S_i × v_i) + S_i δq̇_i      (S_i × S_i = 0 drops the q̇ part)
/// Needs data.v from kinematics(q, v).
inline void tangent_velocity_pass(const Model& model, const Data& data, DerivativeData& d) {
  d.dv_body[0] = model.floating_base ? Vector6(d.direction_v.head<6>()) : Vector6::Zero();
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& S = model.motion_subspace[ui];
    d.dv_body[ui] = data.X_up[ui] * d.dv_body[j] -
                    joint_entry(model, d.direction_q, ui) * (crm(S) * data.v[ui]) +
                    S * joint_entry(model, d.direction_v, ui);
  }
}

/// The tangent of the inward force pass (tree_helpers.hpp's inward_force_pass), from the body
/// wrench tangents δf_i in d.df_body and the accumulated primal wrenches f_i in data.f_body:
///   for i = nb-1 … 1: δτ_i ← S_iᵀ δf_i;  δf_λ(i) ← δf_λ(i) + (X_λ(i)^i)ᵀ (δf_i + δq_i S_i ×* f_i)
///   δτ_0 ← δf_0 (floating base)
/// since δ((X_λ(i)^i)ᵀ) = −δq_i (X_λ(i)^i)ᵀ (S_i×)ᵀ = δq_i (X_λ(i)^i)ᵀ (S_i×*). A rotor's placement X_rot
/// on λ(i) is constant, so its wrench tangent d.df_rotor[i] enters like its wrench does:
///   δτ_i ← δτ_i + S_rotᵀ δf_rot,i;  δf_λ(i) ← δf_λ(i) + X_rotᵀ δf_rot,i.   Writes d.tau_column.
inline void tangent_inward_pass(const Model& model, const Data& data, DerivativeData& d) {
  for (int i = model.nb - 1; i >= 1; --i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& S = model.motion_subspace[ui];
    d.tau_column[model.joints[ui].v_index] = S.dot(d.df_body[ui]);
    const Vector6 df = d.df_body[ui] + joint_entry(model, d.direction_q, ui) * (crf(S) * data.f_body[ui]);
    d.df_body[j].noalias() += data.X_up[ui].transpose() * df;
    if (model.has_rotors) {
      d.tau_column[model.joints[ui].v_index] += model.rotor_subspace[ui].dot(d.df_rotor[ui]);
      d.df_body[j].noalias() += model.X_rotor[ui].transpose() * d.df_rotor[ui];
    }
  }
  if (model.floating_base) d.tau_column.head<6>() = d.df_body[0];
}

/// Sets direction to the unit vector e_column (direction.size() entries, no allocation).
inline void set_unit_direction(VectorX& direction, Eigen::Index column) {
  direction.setZero();
  direction[column] = 1;
}

}  // namespace rbdc::detail
