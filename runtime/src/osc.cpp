// Paper 001: Table 1 (Eqs. 29-41), Table 2 (Eqs. 42-47), Eq. 58, and the closed forms of
// Eqs. 10-13, 16-27. Body numbering: the paper's torso "Body 1" is our body 0, its inertial
// frame "0" is our world W, and the paper's test p(i) ≠ 0 holds for every i ≥ 1 here.
#include "rbdc/osc.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "argument_checks.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rotors.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

namespace {

void check_trunk_task(const char* function, const Model& model) {
  if (!model.floating_base) {
    throw std::invalid_argument(std::string("rbdc::") + function + ": model '" + model.name +
                                "' has a fixed base, so there is no trunk task");
  }
  if (!model.couplings.empty()) {  // the recursion works in tree coordinates (docs/model.md)
    throw std::invalid_argument(std::string("rbdc::") + function + ": model '" + model.name +
                                "' has mimic couplings, which the OSC recursion does not support; "
                                "load it with MimicMode::Lock or MimicMode::Independent");
  }
}

void check_contact_feet(const char* function, const Model& model,
                        const std::vector<int>& contact_feet) {
  const int n_feet = static_cast<int>(model.feet.size());
  for (size_t r = 0; r < contact_feet.size(); ++r) {
    const int k = contact_feet[r];
    if (k < 0 || k >= n_feet || std::count(contact_feet.begin(), contact_feet.end(), k) > 1) {
      throw std::invalid_argument(std::string("rbdc::") + function + ": contact_feet[" +
                                  std::to_string(r) + "] = " + std::to_string(k) +
                                  " is not a foot index in 0 … " + std::to_string(n_feet - 1) +
                                  " or is repeated");
    }
  }
}

/// Gravity as a spatial acceleration in trunk coordinates: ¹X₀ ⁰a_g = (0, R_W^0 g_W).
Vector6 trunk_gravity(const Model& model, const Data& data) {
  Vector6 a_g;
  a_g << Vector3::Zero(), detail::rotation_of(data.X_world[0]) * model.gravity;
  return a_g;
}

// Table 1, outward recursion (the transforms and velocities come from Alg. 1 of paper 000):
//   for i = 1 … N_B: ζ_i = v_i × Φ_i q̇_i;  β_i^A = v_i ×* I_i v_i - f_i^e;  I_i^A = I_i
// f_i^e is data.f_ext (the external wrench on body i, body coordinates).
void outward_pass(const Model& model, Data& data, const VectorRef& v) {
  for (int i = 0; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const Vector6& vi = data.v[ui];
    const Matrix6& Ii = model.inertia[ui];
    data.zeta[ui] = i == 0 ? Vector6::Zero()
                           : Vector6(crm(vi) * model.motion_subspace[ui] *
                                     v[model.joints[ui].v_index]);  // Eq. 29, Φ_i constant
    data.beta[ui] = crf(vi) * Ii * vi - data.f_ext[ui];
    data.IA[ui] = Ii;
    data.B[ui].setZero();
  }
}

// Table 2: for i ∈ C (here: for each foot in contact, on body i = φ(k)), with the contact frame
// c_i at the foot point (Eq. 16) and a ground inertia I_ci = M_ground·1₆ behind a spherical joint
// (free modes Φ_ci = [1₃; 0]):
//   K_ci = Φ_ci (Φ_ciᵀ I_ci Φ_ci)⁻¹ Φ_ciᵀ;  L_ciᵀ = 1 - I_ci K_ci
//   β̃_i^A += ^{c_i}X_iᵀ L_ciᵀ I_ci ^{c_i}X_0 ⁰a_g        (Eq. 47)
//   Ĩ_i^A += ^{c_i}X_iᵀ L_ciᵀ I_ci ^{c_i}X_i             (Eq. 46)
// ("+=" so that two feet on one body both count; with one foot it is the paper's "=").
void pin_contacts(const Model& model, Data& data, const std::vector<int>& contact_feet,
                  double ground_mass) {
  const Matrix6 I_c = ground_mass * Matrix6::Identity();
  Eigen::Matrix<double, 6, 3> Phi_c = Eigen::Matrix<double, 6, 3>::Zero();
  Phi_c.topRows<3>().setIdentity();
  const Matrix6 K_c = Phi_c * (Phi_c.transpose() * I_c * Phi_c).inverse() * Phi_c.transpose();
  const Matrix6 LT_c = Matrix6::Identity() - I_c * K_c;
  Vector6 a_g_world;
  a_g_world << Vector3::Zero(), model.gravity;
  for (const int k : contact_feet) {
    const Foot& foot = model.feet[static_cast<size_t>(k)];
    const size_t i = static_cast<size_t>(foot.body);
    const Matrix6 X_c_i = detail::foot_transform(foot);       // ^{c_i}X_i
    const Matrix6 X_c_0 = X_c_i * data.X_world[i];            // ^{c_i}X_0 = ^{c_i}X_i ^iX_0
    data.beta[i] += X_c_i.transpose() * LT_c * I_c * X_c_0 * a_g_world;
    data.IA[i] += X_c_i.transpose() * LT_c * I_c * X_c_i;
  }
}

// Table 1, inward recursion, for i = N_B … 1 (ours: nb-1 … 1, p(i) = λ(i) always a body):
//   D_i = (Φ_iᵀ I_i^A Φ_i)⁻¹;  K_i = Φ_i D_i Φ_iᵀ;  L_iᵀ = 1 - I_i^A K_i
//   I_p^A += ^iX_pᵀ L_iᵀ I_i^A ^iX_p                     (update after Eq. 37)
//   β_p^A += ^iX_pᵀ L_iᵀ (β_i^A + I_i^A ζ_i)
//   B_pi = -^iX_pᵀ I_i^A Φ_i D_i
//   B_pk = ^iX_pᵀ L_iᵀ B_ik  for all k ∈ c*(i)
// written with U_i = ^iX_pᵀ I_i^A Φ_i (^iX_pᵀ L_iᵀ x = ^iX_pᵀ x - U_i D_i Φ_iᵀ x) so that joint i's
// rotor (rotors.hpp), a leaf body on p spinning with q̇_i, joins in as in Cheetah-Software's
// articulated-body algorithm, and its armature adds to the pivot:
//   U_i += X_rotᵀ I_rot S_rot;  D_i⁻¹ += S_rotᵀ I_rot S_rot + armature_i
//   I_p^A += X_rotᵀ I_rot X_rot;  β_p^A += X_rotᵀ p_rot, with Φ_iᵀ(β_i^A + I_i^A ζ_i) += S_rotᵀ p_rot
//   p_rot = v_rot ×* I_rot v_rot + I_rot (v_rot × S_rot q̇_i)   (β and ζ of the rotor)
void inward_pass(const Model& model, Data& data, const VectorRef& v) {
  for (int i = model.nb - 1; i >= 1; --i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t p = static_cast<size_t>(model.parent[ui]);
    const Vector6& Phi = model.motion_subspace[ui];
    const Matrix6& X = data.X_up[ui];
    const Matrix6& IA = data.IA[ui];
    const Vector6 bias = data.beta[ui] + IA * data.zeta[ui];
    Vector6 U = X.transpose() * (IA * Phi);
    double pivot = Phi.dot(IA * Phi) + model.joints[ui].armature;
    double bias_along_joint = Phi.dot(bias);
    Matrix6 IA_p = X.transpose() * IA * X;
    Vector6 beta_p = X.transpose() * bias;
    if (model.has_rotors) {
      const Matrix6& X_r = model.X_rotor[ui];
      const Matrix6& I_r = model.rotor_inertia[ui];
      const Vector6& S_r = model.rotor_subspace[ui];
      const double qd = v[model.joints[ui].v_index];
      const Vector6 v_r = detail::rotor_velocity(model, data, ui, qd);
      const Vector6 p_r = crf(v_r) * I_r * v_r + I_r * (crm(v_r) * S_r * qd);
      U += X_r.transpose() * (I_r * S_r);
      pivot += S_r.dot(I_r * S_r);
      bias_along_joint += S_r.dot(p_r);
      IA_p += X_r.transpose() * I_r * X_r;
      beta_p += X_r.transpose() * p_r;
    }
    const double D = 1.0 / pivot;
    data.IA[p] += IA_p - U * D * U.transpose();
    data.beta[p] += beta_p - U * (D * bias_along_joint);
    data.B[p].col(i - 1) = -U * D;
    for (const int k : model.subtree[ui]) {
      if (k == i) continue;
      const auto B_ik = data.B[ui].col(k - 1);
      data.B[p].col(k - 1) = X.transpose() * B_ik - U * (D * Phi.dot(B_ik));
    }
  }
}

// Outputs of Tables 1-2: Λ_t = I_1^A; J̄_tᵀ = [B_12 … B_1N_B] (the identity block for f_t is
// left out); b_t = β_1^A - I_1^A (¹X₀ ⁰a_g + (0, ω_1 × v_1))                     (Eqs. 39-41)
const OscQuantities& recursion_outputs(const Model& model, Data& data) {
  const Vector6& v0 = data.v[0];
  Vector6 correction = trunk_gravity(model, data);
  correction.tail<3>() += v0.head<3>().cross(v0.tail<3>());
  data.osc.Lambda = data.IA[0];
  data.osc.JbarT = data.B[0];
  data.osc.b = data.beta[0] - data.IA[0] * correction;
  return data.osc;
}

/// H⁻¹ into reference.M_inv by Data's preallocated Cholesky factor; J_t = [1₆ 0] into
/// reference.J_t.
void invert_mass_matrix_and_set_task_jacobian(Data& data, OscReferenceData& reference) {
  data.M_llt.compute(data.M);
  reference.M_inv.setIdentity();
  data.M_llt.solveInPlace(reference.M_inv);
  reference.J_t.setZero();
  reference.J_t.leftCols<6>().setIdentity();
}

}  // namespace

OscReferenceData::OscReferenceData(const Model& model) {
  const Eigen::Index nv = model.nv;
  const Eigen::Index n_feet = static_cast<Eigen::Index>(model.feet.size());
  result.JbarT = Matrix6X::Zero(6, model.num_joints());
  M_inv = MatrixX::Zero(nv, nv);
  J_t = Matrix6X::Zero(6, nv);
  J_t_M_inv = Matrix6X::Zero(6, nv);
  J_t_M_inv_N_cT = Matrix6X::Zero(6, nv);
  JbarT_full = Matrix6X::Zero(6, nv);
  J_c = MatrixX::Zero(3 * n_feet, nv);
  J_c_M_inv = MatrixX::Zero(3 * n_feet, nv);
  A_c = MatrixX::Zero(3 * n_feet, 3 * n_feet);
  N_cT = MatrixX::Zero(nv, nv);
  contact_bias = VectorX::Zero(3 * n_feet);
  work_nv = VectorX::Zero(nv);
}

double default_ground_mass(const Model& model) {
  double m_min = std::numeric_limits<double>::infinity();
  for (const Body& b : model.bodies) {
    if (b.mass > 0) m_min = std::min(m_min, b.mass);
  }
  return m_min / std::sqrt(std::numeric_limits<double>::epsilon());
}

const OscQuantities& osc_open_chain(const Model& model, Data& data, const VectorRef& q,
                                    const VectorRef& v, const Matrix3X& f_feet_world) {
  detail::check_qv("osc_open_chain", model, data, q, v);
  detail::check_invertible_mass("osc_open_chain", model);
  detail::check_feet_matrix("osc_open_chain", "f_feet_world", model, f_feet_world);
  check_trunk_task("osc_open_chain", model);
  // f_i^e: the measured foot forces as body wrenches (the same construction as Alg. 4's input)
  feet_force_terms(model, data, q, f_feet_world);
  kinematics(model, data, q, v);
  outward_pass(model, data, v);
  inward_pass(model, data, v);
  return recursion_outputs(model, data);
}

const OscQuantities& osc_closed_chain(const Model& model, Data& data, const VectorRef& q,
                                      const VectorRef& v, const std::vector<int>& contact_feet,
                                      double ground_mass) {
  detail::check_qv("osc_closed_chain", model, data, q, v);
  detail::check_invertible_mass("osc_closed_chain", model);
  check_trunk_task("osc_closed_chain", model);
  check_contact_feet("osc_closed_chain", model, contact_feet);
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  for (Vector6& f : data.f_ext) f.setZero();  // no measured forces: β̃_i^A starts at v_i ×* I_i v_i
  outward_pass(model, data, v);
  pin_contacts(model, data, contact_feet, ground_mass);
  inward_pass(model, data, v);
  return recursion_outputs(model, data);
}

const OscQuantities& osc_closed_chain(const Model& model, Data& data, const VectorRef& q,
                                      const VectorRef& v, const std::vector<int>& contact_feet) {
  return osc_closed_chain(model, data, q, v, contact_feet, default_ground_mass(model));
}

const OscQuantities& osc_closed_form(const Model& model, Data& data, OscReferenceData& reference,
                                     const VectorRef& q, const VectorRef& v,
                                     const Matrix3X& f_feet_world) {
  detail::check_qv("osc_closed_form", model, data, q, v);
  detail::check_invertible_mass("osc_closed_form", model);
  detail::check_feet_matrix("osc_closed_form", "f_feet_world", model, f_feet_world);
  check_trunk_task("osc_closed_form", model);
  mass_matrix(model, data, q);
  quadratic_velocity_terms(model, data, q, v);
  gravity_terms(model, data, q);
  feet_force_terms(model, data, q, f_feet_world);  // τ_e = J_cᵀ F_c (App. B of paper 000)
  invert_mass_matrix_and_set_task_jacobian(data, reference);
  OscQuantities& out = reference.result;
  reference.J_t_M_inv.noalias() = reference.J_t * reference.M_inv;
  // Λ_t = (J_t H⁻¹ J_tᵀ)⁻¹                                              (Eq. 10)
  const Matrix6 Lambda_inv = reference.J_t_M_inv * reference.J_t.transpose();
  out.Lambda = Lambda_inv.inverse();
  // J̄_tᵀ = Λ_t J_t H⁻¹                                                  (Eq. 11)
  reference.JbarT_full.noalias() = out.Lambda * reference.J_t_M_inv;
  out.JbarT = reference.JbarT_full.rightCols(model.num_joints());  // Sᵀ picks the actuated columns
  // μ_t + ρ_t - J̄_tᵀ J_cᵀ F_c = J̄_tᵀ (C + G - τ_e); J̇_t = 0        (Eqs. 12, 13, 27)
  reference.work_nv = data.c + data.g - data.tau_e;
  out.b.noalias() = reference.JbarT_full * reference.work_nv;
  return out;
}

const OscQuantities& osc_closed_form_constrained(const Model& model, Data& data,
                                                 OscReferenceData& reference, const VectorRef& q,
                                                 const VectorRef& v,
                                                 const std::vector<int>& contact_feet) {
  detail::check_qv("osc_closed_form_constrained", model, data, q, v);
  detail::check_invertible_mass("osc_closed_form_constrained", model);
  check_trunk_task("osc_closed_form_constrained", model);
  check_contact_feet("osc_closed_form_constrained", model, contact_feet);
  mass_matrix(model, data, q);
  quadratic_velocity_terms(model, data, q, v);
  gravity_terms(model, data, q);
  feet_jacobian(model, data, q);
  feet_bias_accelerations(model, data, q, v);
  invert_mass_matrix_and_set_task_jacobian(data, reference);
  OscQuantities& out = reference.result;

  // J_c and J̇_c v: the world rows of the feet in contact (Eq. 16)
  const Eigen::Index m = 3 * static_cast<Eigen::Index>(contact_feet.size());
  for (size_t r = 0; r < contact_feet.size(); ++r) {
    const Eigen::Index k = contact_feet[r];
    const Eigen::Index row = 3 * static_cast<Eigen::Index>(r);
    reference.J_c.middleRows<3>(row) = data.J.middleRows<3>(3 * k);
    reference.contact_bias.segment<3>(row) = data.feet_bias_acceleration.col(k);
  }
  const auto J_c = reference.J_c.topRows(m);
  auto JbarT_c = reference.J_c_M_inv.topRows(m);
  auto Lambda_c_Jdot_v = reference.contact_bias.head(m);
  // Λ_c⁻¹ = J_c H⁻¹ J_cᵀ, factorised in place (no allocation)
  JbarT_c.noalias() = J_c * reference.M_inv;
  Eigen::Ref<MatrixX> A_c = reference.A_c.topLeftCorner(m, m);
  A_c.noalias() = JbarT_c * J_c.transpose();
  Eigen::LLT<Eigen::Ref<MatrixX>> A_c_llt(A_c);
  // J̄_cᵀ = Λ_c J_c H⁻¹ and Λ_c J̇_c v
  A_c_llt.solveInPlace(JbarT_c);
  A_c_llt.solveInPlace(Lambda_c_Jdot_v);
  // N_cᵀ = 1 - J_cᵀ J̄_cᵀ                                               (after Eq. 17)
  reference.N_cT.setIdentity();
  reference.N_cT.noalias() -= J_c.transpose() * JbarT_c;
  // Λ̃_t = (J_t H⁻¹ N_cᵀ J_tᵀ)⁻¹                                         (Eq. 20)
  reference.J_t_M_inv.noalias() = reference.J_t * reference.M_inv;
  reference.J_t_M_inv_N_cT.noalias() = reference.J_t_M_inv * reference.N_cT;
  const Matrix6 Lambda_inv = reference.J_t_M_inv_N_cT * reference.J_t.transpose();
  out.Lambda = Lambda_inv.inverse();
  // J̃_tᵀ = Λ̃_t J_t H⁻¹ N_cᵀ                                             (Eq. 22)
  reference.JbarT_full.noalias() = out.Lambda * reference.J_t_M_inv_N_cT;
  out.JbarT = reference.JbarT_full.rightCols(model.num_joints());
  // b̃_t = μ̃_t + ρ̃_t = J̃_tᵀ (C + G) + Λ̃_t J_t H⁻¹ J_cᵀ Λ_c J̇_c v       (Eqs. 25-26)
  reference.work_nv.noalias() = J_c.transpose() * Lambda_c_Jdot_v;
  const Vector6 contact_term = out.Lambda * (reference.J_t_M_inv * reference.work_nv);
  reference.work_nv = data.c + data.g;
  out.b.noalias() = reference.JbarT_full * reference.work_nv;
  out.b += contact_term;
  return out;
}

}  // namespace rbdc
