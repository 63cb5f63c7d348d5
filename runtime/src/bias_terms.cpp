// Paper 000 Algs. 2-4.
#include "rbdc/bias_terms.hpp"

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"
#include "rotors.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

const VectorX& quadratic_velocity_terms(const Model& model, Data& data, const VectorRef& q,
                                        const VectorRef& v) {
  detail::check_qv("quadratic_velocity_terms", model, data, q, v);
  kinematics(model, data, q, v);
  const Vector6& v0 = data.v[0];
  // a_0 ← (0_3, -ω̃_0 v_0)        (zero for a fixed base, where v_0 = 0)
  data.a_body[0] << Vector3::Zero(), -v0.head<3>().cross(v0.tail<3>());
  // f_0 ← I_0 a_0 + v_0 ⊗ I_0 v_0
  data.f_body[0] = model.inertia[0] * data.a_body[0] + crf(v0) * model.inertia[0] * v0;
  // for i = 1 … nb-1
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& vi = data.v[ui];
    const Matrix6& Ii = model.inertia[ui];
    //   a_i ← X_j^i a_j + v_i * S_i q̇_i                     (Eq. 19)
    data.a_body[ui] = data.X_up[ui] * data.a_body[j] +
                      crm(vi) * model.motion_subspace[ui] * v[model.joints[ui].v_index];
    //   f_i ← I_i a_i + v_i ⊗ I_i v_i                       (Eq. 20)
    data.f_body[ui] = Ii * data.a_body[ui] + crf(vi) * Ii * vi;
    //   rotor i on body j: f_rot,i at q̈ = 0 (rotors.hpp)
    if (model.has_rotors) {
      data.f_rotor[ui] = detail::rotor_wrench(model, ui, data.v[j], data.a_body[j],
                                              v[model.joints[ui].v_index], 0.0);
    }
  }
  // for i = nb-1 … 1: c_i ← S_iᵀ f_i; f_j ← f_j + (X_j^i)ᵀ f_i; then c_0 ← S_0ᵀ f_0  (Eqs. 22-23)
  detail::inward_force_pass(model, data, data.c);
  return data.c;
}

const VectorX& gravity_terms(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("gravity_terms", model, data, q);
  kinematics(model, data, q);
  // a_0 ← -(0_3, R_W^0 g_W)
  data.a_body[0] << Vector3::Zero(), -detail::rotation_of(data.X_world[0]) * model.gravity;
  // f_0 ← I_0 a_0
  data.f_body[0] = model.inertia[0] * data.a_body[0];
  // for i = 1 … nb-1: a_i ← X_j^i a_j; f_i ← I_i a_i        (Eq. 24)
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    data.a_body[ui] = data.X_up[ui] * data.a_body[j];
    data.f_body[ui] = model.inertia[ui] * data.a_body[ui];
    //   rotor i on body j: f_rot,i ← I_rot X_rot a_j
    if (model.has_rotors) {
      data.f_rotor[ui] = detail::rotor_wrench(model, ui, Vector6::Zero(), data.a_body[j], 0.0, 0.0);
    }
  }
  // for i = nb-1 … 1: g_i ← S_iᵀ f_i; f_j ← f_j + (X_j^i)ᵀ f_i; then g_0 ← S_0ᵀ f_0  (Eqs. 22, 25)
  detail::inward_force_pass(model, data, data.g);
  return data.g;
}

const VectorX& external_wrench_terms(const Model& model, Data& data, const VectorRef& q,
                                     const std::vector<Vector6>& f_ext) {
  detail::check_q("external_wrench_terms", model, data, q);
  detail::check_size("external_wrench_terms", "f_ext", static_cast<Eigen::Index>(f_ext.size()),
                     model.nb);
  kinematics(model, data, q);
  // for i = 0 … nb-1: f_i ← X̄_{F_i}^i f_ext,i  (the wrenches are given at F_i = body frame i)
  for (size_t i = 0; i < f_ext.size(); ++i) data.f_body[i] = f_ext[i];
  // Rotors take no external wrench; they only carry the bodies' wrenches, so f_rot = 0.
  if (model.has_rotors) {
    for (Vector6& f : data.f_rotor) f.setZero();
  }
  // for i = nb-1 … 1: τ_ei ← S_iᵀ f_i; f_j ← f_j + (X_j^i)ᵀ f_i; then τ_e0 ← S_0ᵀ f_0
  detail::inward_force_pass(model, data, data.tau_e);
  return data.tau_e;
}

const VectorX& feet_force_terms(const Model& model, Data& data, const VectorRef& q,
                                const Matrix3X& f_world) {
  detail::check_q("feet_force_terms", model, data, q);
  detail::check_feet_matrix("feet_force_terms", "f_world", model, f_world);
  world_transforms(model, data, q);
  for (Vector6& f : data.f_ext) f.setZero();
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Foot& foot = model.feet[k];
    const size_t i = static_cast<size_t>(foot.body);
    // The foot frame {fk} has body i's orientation (Eq. 16): f^fk = (0, R_W^i f^W).
    Vector6 f_fk;
    f_fk << Vector3::Zero(), detail::rotation_of(data.X_world[i]) * f_world.col(static_cast<Eigen::Index>(k));
    // X̄_fk^i f^fk = (X_i^fk)ᵀ f^fk                          (Eqs. 8, 16)
    data.f_ext[i].noalias() += detail::foot_transform(foot).transpose() * f_fk;
  }
  return external_wrench_terms(model, data, q, data.f_ext);
}

}  // namespace rbdc
