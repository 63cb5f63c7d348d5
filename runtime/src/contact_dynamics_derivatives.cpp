// ∂(a, λ)/∂(q, v, τ) of contact_dynamics by differentiating its KKT system at the solution
// (Carpentier & Mansard, RSS 2018, Sec. "derivatives of constrained dynamics"; the idea, not
// Pinocchio's code): both rows are differentiated at fixed (a, λ) with the existing tangent passes,
// then the KKT matrix is inverted through its Schur complement, A = J M⁻¹Jᵀ, as in the primal solve.
// Equations: docs/runtime.md, "Contact dynamics".
#include <limits>

#include "argument_checks.hpp"
#include "contact_solve.hpp"
#include "derivative_passes.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

namespace {

/// The primal accelerations a_i at the given a (no gravity): the trunk's spatial acceleration
/// a_0 = a[0:6] + (0, −ω_0 × v_0) (conventions.md), a_i = X_λ(i)^i a_λ(i) + S_i q̈_i + v_i × S_i q̇_i
/// (paper 000 Eq. 19). Needs kinematics(q, v) in data.
void acceleration_pass(const Model& model, Data& data, const VectorRef& v, const VectorRef& a) {
  data.a_body[0].setZero();
  if (model.floating_base) {
    data.a_body[0] = a.head<6>();
    data.a_body[0].tail<3>() -= data.v[0].head<3>().cross(data.v[0].tail<3>());
  }
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& S = model.motion_subspace[ui];
    const Eigen::Index k = model.joints[ui].v_index;
    data.a_body[ui] = data.X_up[ui] * data.a_body[j] + S * a[k] + crm(data.v[ui]) * S * v[k];
  }
}

/// The tangent of acceleration_pass at fixed a for the direction in d (after the motion and
/// velocity tangent passes): δa_0 = (0, −δω_0 × v_0 − ω_0 × δv_0) (floating base), and
///   δa_i = X_λ(i)^i δa_λ(i) − δq_i S_i × (X_λ(i)^i a_λ(i)) + δv_i × S_i q̇_i + v_i × S_i δq̇_i.
void tangent_acceleration_pass(const Model& model, const Data& data, DerivativeData& d,
                               const VectorRef& v) {
  d.da_body[0].setZero();
  if (model.floating_base) {
    const Vector6& v0 = data.v[0];
    const Vector6& dv0 = d.dv_body[0];
    d.da_body[0].tail<3>() = -dv0.head<3>().cross(v0.tail<3>()) - v0.head<3>().cross(dv0.tail<3>());
  }
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& S = model.motion_subspace[ui];
    d.da_body[ui] = data.X_up[ui] * d.da_body[j] -
                    detail::joint_entry(model, d.direction_q, ui) *
                        (crm(S) * (data.X_up[ui] * data.a_body[j])) +
                    crm(d.dv_body[ui]) * S * detail::joint_entry(model, v, ui) +
                    crm(data.v[ui]) * S * detail::joint_entry(model, d.direction_v, ui);
  }
}

/// Column `column` of ∂p/∂q, ∂ṗ/∂q, ∂p̈/∂q (q direction) or of ∂p̈/∂v (v direction) for the
/// contact points. With u = lin(X_fk a_i) + ang(X_fk v_i) × lin(X_fk v_i), p̈ = R_i^W u (the
/// classical acceleration, as feet_bias_accelerations) and δR_i^W = R_i^W ψ̃_i,ang:
///   δp̈ = R_i^W (ψ_i,ang × u + δu),  δṗ = R_i^W (ψ_i,ang × lin(X_fk v_i) + lin(X_fk δv_i)),
///   δp = R_i^W lin(X_fk ψ_i).
void contact_point_tangents(const Model& model, const Data& data, const DerivativeData& d,
                            ContactDynamicsData& contact, Eigen::Index column, bool q_direction) {
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    const Foot& foot = model.feet[static_cast<size_t>(contact.contact_feet[k])];
    const size_t i = static_cast<size_t>(foot.body);
    const Matrix6 X_fk = detail::foot_transform(foot);
    const Matrix3 world_R_body = detail::rotation_of(data.X_world[i]).transpose();
    const Vector6 v_f = X_fk * data.v[i], dv_f = X_fk * d.dv_body[i], da_f = X_fk * d.da_body[i];
    const Vector3 u = (X_fk * data.a_body[i]).tail<3>() + v_f.head<3>().cross(v_f.tail<3>());
    const Vector3 du = da_f.tail<3>() + dv_f.head<3>().cross(v_f.tail<3>()) +
                       v_f.head<3>().cross(dv_f.tail<3>());
    const Vector3 psi = d.dX_motion[i].head<3>();
    const Eigen::Index row = 3 * static_cast<Eigen::Index>(k);
    if (!q_direction) {
      contact.dpddot_dv.block<3, 1>(row, column) = world_R_body * du;
      continue;
    }
    contact.dpddot_dq.block<3, 1>(row, column) = world_R_body * (psi.cross(u) + du);
    contact.dpdot_dq.block<3, 1>(row, column) =
        world_R_body * (psi.cross(v_f.tail<3>()) + dv_f.tail<3>());
    contact.dp_dq.block<3, 1>(row, column) = world_R_body * (X_fk * d.dX_motion[i]).tail<3>();
  }
}

/// ∂p, ∂ṗ, ∂p̈ of the contact points at fixed a, one tangent pass per direction.
void contact_point_derivatives(const Model& model, Data& data, DerivativeData& d,
                               ContactDynamicsData& contact, const VectorRef& q,
                               const VectorRef& v, const VectorRef& a) {
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  acceleration_pass(model, data, v, a);
  for (bool q_direction : {true, false}) {
    d.direction_q.setZero();
    d.direction_v.setZero();
    for (Eigen::Index column = 0; column < model.nv; ++column) {
      detail::set_unit_direction(q_direction ? d.direction_q : d.direction_v, column);
      detail::tangent_motion_pass(model, data, d);
      detail::tangent_velocity_pass(model, data, d);
      tangent_acceleration_pass(model, data, d, v);
      contact_point_tangents(model, data, d, contact, column, q_direction);
    }
  }
  d.direction_q.setZero();
  d.direction_v.setZero();
}

/// From the KKT rows' derivatives r₁ (nv rows) and r₂ (m rows, null for zero):
///   ∂λ = A⁻¹(J M⁻¹ r₁ − r₂),  ∂a = M⁻¹(Jᵀ∂λ − r₁).
void solve_kkt_derivative(const Data& data, ContactDynamicsData& contact, const MatrixX& r_joint,
                          const MatrixX* r_contact, MatrixX& da, MatrixX& dlambda) {
  dlambda.noalias() = contact.Minv_Jt.transpose() * r_joint;  // J M⁻¹ = (M⁻¹Jᵀ)ᵀ
  if (r_contact != nullptr) dlambda -= *r_contact;
  for (Eigen::Index k = 0; k < dlambda.cols(); ++k) {
    contact.rhs = dlambda.col(k);
    detail::solve_delassus(contact, dlambda.col(k));
  }
  da.noalias() = contact.J.transpose() * dlambda;
  da -= r_joint;
  detail::solve_with_mass_matrix(data, da);
}

void derivatives_at(const Model& model, Data& data, DerivativeData& d, ContactDynamicsData& contact,
                    const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                    const Matrix3X* anchors) {
  detail::check_derivative_data("contact_dynamics_derivatives", model, d);
  detail::solve_contact_dynamics(model, data, contact, q, v, tau, anchors);
  if (data.M_llt.info() != Eigen::Success) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (MatrixX* m : {&contact.da_dq, &contact.da_dv, &contact.da_dtau, &contact.dlambda_dq,
                       &contact.dlambda_dv, &contact.dlambda_dtau}) {
      m->setConstant(nan);
    }
    return;
  }
  // Row 1, M a + c + g − Jᵀλ − Sᵀτ, at fixed (a, λ): ∂τ/∂(q, v) of the RNEA at a, and ∂(Jᵀλ)/∂q
  // with λ summed per foot (repeated contacts add up)
  contact.f_feet.setZero();
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    contact.f_feet.col(contact.contact_feet[k]) +=
        contact.lambda.segment<3>(3 * static_cast<Eigen::Index>(k));
  }
  feet_force_term_derivatives(model, data, d, q, contact.f_feet);
  inverse_dynamics_derivatives(model, data, d, q, v, contact.a);
  // Row 2, J a + J̇v + kd J v + kp (p − p*) = p̈ + kd ṗ + kp (p − p*), at fixed a
  contact_point_derivatives(model, data, d, contact, q, v, contact.a);
  const double kp = anchors != nullptr ? contact.gains.kp : 0.0, kd = contact.gains.kd;
  // ∂/∂q: r₁ = ∂τ/∂q − ∂(Jᵀλ)/∂q,  r₂ = ∂p̈/∂q + kd ∂ṗ/∂q + kp ∂p/∂q
  contact.r_joint = d.dtau_dq - d.dtau_e_dq;
  contact.r_contact = contact.dpddot_dq + kd * contact.dpdot_dq + kp * contact.dp_dq;
  solve_kkt_derivative(data, contact, contact.r_joint, &contact.r_contact, contact.da_dq,
                       contact.dlambda_dq);
  // ∂/∂v: r₁ = ∂τ/∂v,  r₂ = ∂p̈/∂v + kd J
  contact.r_contact = contact.dpddot_dv + kd * contact.J;
  solve_kkt_derivative(data, contact, d.dtau_dv, &contact.r_contact, contact.da_dv,
                       contact.dlambda_dv);
  // ∂/∂τ: r₁ = −Sᵀ (the joint rows), r₂ = 0
  contact.r_tau.setZero();
  contact.r_tau.bottomRows(model.num_joints()).setIdentity();
  contact.r_tau *= -1;
  solve_kkt_derivative(data, contact, contact.r_tau, nullptr, contact.da_dtau, contact.dlambda_dtau);
}

}  // namespace

void contact_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  ContactDynamicsData& contact, const VectorRef& q,
                                  const VectorRef& v, const VectorRef& tau) {
  detail::check_contact_call("contact_dynamics_derivatives", model, data, contact, q, v, tau);
  derivatives_at(model, data, derivatives, contact, q, v, tau,
                 detail::checked_anchors("contact_dynamics_derivatives", contact, nullptr));
}

void contact_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  ContactDynamicsData& contact, const VectorRef& q,
                                  const VectorRef& v, const VectorRef& tau, const Matrix3X& anchors) {
  detail::check_contact_call("contact_dynamics_derivatives", model, data, contact, q, v, tau);
  derivatives_at(model, data, derivatives, contact, q, v, tau,
                 detail::checked_anchors("contact_dynamics_derivatives", contact, &anchors));
}

}  // namespace rbdc
