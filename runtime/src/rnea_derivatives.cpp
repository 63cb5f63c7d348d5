// Derivatives of the RNEA (inverse_dynamics.cpp) by a hand-written tangent pass per direction:
// ∂τ/∂q, ∂τ/∂v, and their a = 0 (c + g) and v = a = 0 (g) cases. Equations: docs/runtime.md.
#include "argument_checks.hpp"
#include "derivative_passes.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

namespace {

/// δτ for the direction (d.direction_q, d.direction_v) at δa = 0, after inverse_dynamics(q, v, a)
/// has left X_up, v_i, a_i and the accumulated f_i in data. v: the primal joint rates. Writes
/// d.tau_column.
void rnea_tangent(const Model& model, const Data& data, DerivativeData& d, const VectorRef& v) {
  detail::tangent_velocity_pass(model, data, d);
  const Vector6& v0 = data.v[0];
  const Vector6& dv0 = d.dv_body[0];
  // δa_0 = δ(a[0:6] + (0, −ω̃_0 v_0) − (0, R_W^0 g_W)) with δR_W^0 = −δθ̃ R_W^0:
  //   (0, −δω_0 × v_0 − ω_0 × δv_0 + δθ × R_W^0 g_W)      (zero for a fixed base)
  d.da_body[0].setZero();
  if (model.floating_base) {
    const Vector3 gravity_trunk = detail::rotation_of(data.X_world[0]) * model.gravity;
    d.da_body[0].tail<3>() = -dv0.head<3>().cross(v0.tail<3>()) -
                             v0.head<3>().cross(dv0.tail<3>()) +
                             d.direction_q.head<3>().cross(gravity_trunk);
  }
  // δf_0 = I_0 δa_0 + δv_0 ⊗ I_0 v_0 + v_0 ⊗ I_0 δv_0
  const Matrix6& I0 = model.inertia[0];
  d.df_body[0] = I0 * d.da_body[0] + crf(dv0) * (I0 * v0) + crf(v0) * (I0 * dv0);
  // for i = 1 … nb-1
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const Vector6& S = model.motion_subspace[ui];
    const Matrix6& Ii = model.inertia[ui];
    const Vector6& vi = data.v[ui];
    const Vector6& dvi = d.dv_body[ui];
    const double qd_i = detail::joint_entry(model, v, ui);
    const double dq_i = detail::joint_entry(model, d.direction_q, ui);
    const double dqd_i = detail::joint_entry(model, d.direction_v, ui);
    //   δa_i = X_j^i δa_j − δq_i S_i × (X_j^i a_j) + δv_i × S_i q̇_i + v_i × S_i δq̇_i  (δ of Eq. 19)
    d.da_body[ui] = data.X_up[ui] * d.da_body[j] -
                    dq_i * (crm(S) * (data.X_up[ui] * data.a_body[j])) +
                    crm(dvi) * S * qd_i + crm(vi) * S * dqd_i;
    //   δf_i = I_i δa_i + δv_i ⊗ I_i v_i + v_i ⊗ I_i δv_i                               (δ of Eq. 20)
    d.df_body[ui] = Ii * d.da_body[ui] + crf(dvi) * (Ii * vi) + crf(vi) * (Ii * dvi);
    //   rotor i on body j (rotors.hpp's rotor_wrench differentiated; X_rot is constant):
    //   δv_r = X_rot δv_j + S_rot δq̇_i,  δa_r = X_rot δa_j + δv_r × S_rot q̇_i + v_r × S_rot δq̇_i,
    //   δf_r = I_rot δa_r + δv_r ⊗ I_rot v_r + v_r ⊗ I_rot δv_r
    if (model.has_rotors) {
      const Vector6& S_r = model.rotor_subspace[ui];
      const Matrix6& I_r = model.rotor_inertia[ui];
      const Matrix6& X_r = model.X_rotor[ui];
      const Vector6 v_r = X_r * data.v[j] + S_r * qd_i;
      const Vector6 dv_r = X_r * d.dv_body[j] + S_r * dqd_i;
      const Vector6 da_r = X_r * d.da_body[j] + crm(dv_r) * S_r * qd_i + crm(v_r) * S_r * dqd_i;
      d.df_rotor[ui] = I_r * da_r + crf(dv_r) * (I_r * v_r) + crf(v_r) * (I_r * dv_r);
    }
  }
  // δτ_i = S_iᵀ δf_i through the differentiated inward pass                           (δ of Eqs. 21-23)
  detail::tangent_inward_pass(model, data, d);
}

/// One tangent pass per column: ∂τ/∂q into d_dq and, unless null, ∂τ/∂v into d_dv, at the state of
/// the last inverse_dynamics call (whose joint rates are v).
void rnea_derivative_columns(const Model& model, const Data& data, DerivativeData& d,
                             const VectorRef& v, MatrixX& d_dq, MatrixX* d_dv) {
  d.direction_v.setZero();
  for (Eigen::Index k = 0; k < model.nv; ++k) {
    detail::set_unit_direction(d.direction_q, k);
    rnea_tangent(model, data, d, v);
    d_dq.col(k) = d.tau_column;
  }
  d.direction_q.setZero();
  if (d_dv == nullptr) return;
  for (Eigen::Index k = 0; k < model.nv; ++k) {
    detail::set_unit_direction(d.direction_v, k);
    rnea_tangent(model, data, d, v);
    d_dv->col(k) = d.tau_column;
  }
  d.direction_v.setZero();
}

}  // namespace

void inverse_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  const VectorRef& q, const VectorRef& v, const VectorRef& a) {
  detail::check_derivative_data("inverse_dynamics_derivatives", model, derivatives);
  detail::check_qv("inverse_dynamics_derivatives", model, data, q, v);
  detail::check_size("inverse_dynamics_derivatives", "a", a.size(), model.nv);
  inverse_dynamics(model, data, q, v, a);
  rnea_derivative_columns(model, data, derivatives, v, derivatives.dtau_dq, &derivatives.dtau_dv);
}

void bias_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                      const VectorRef& q, const VectorRef& v) {
  detail::check_derivative_data("bias_derivatives", model, derivatives);
  detail::check_qv("bias_derivatives", model, data, q, v);
  // c + g is the RNEA at a = 0
  inverse_dynamics(model, data, q, v, derivatives.zero_nv);
  rnea_derivative_columns(model, data, derivatives, v, derivatives.dbias_dq, &derivatives.dbias_dv);
}

void gravity_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                         const VectorRef& q) {
  detail::check_derivative_data("gravity_derivatives", model, derivatives);
  detail::check_q("gravity_derivatives", model, data, q);
  // g is the RNEA at v = a = 0
  inverse_dynamics(model, data, q, derivatives.zero_nv, derivatives.zero_nv);
  rnea_derivative_columns(model, data, derivatives, derivatives.zero_nv, derivatives.dg_dq, nullptr);
}

}  // namespace rbdc
