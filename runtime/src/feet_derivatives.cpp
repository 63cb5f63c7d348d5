// ∂/∂q of the feet velocities (Eq. 37) and of the feet force terms Jᵀf (Alg. 4 with the wrenches of
// feet_force_terms), by tangent passes per direction. Equations: docs/runtime.md, "Derivatives".
#include "argument_checks.hpp"
#include "derivative_passes.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

void feet_velocity_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                               const VectorRef& q, const VectorRef& v) {
  detail::check_derivative_data("feet_velocity_derivatives", model, derivatives);
  detail::check_qv("feet_velocity_derivatives", model, data, q, v);
  DerivativeData& d = derivatives;
  feet_velocities(model, data, q, v);  // kinematics(q, v) and X_W^i
  d.direction_v.setZero();
  for (Eigen::Index column = 0; column < model.nv; ++column) {
    detail::set_unit_direction(d.direction_q, column);
    detail::tangent_motion_pass(model, data, d);    // ψ_i
    detail::tangent_velocity_pass(model, data, d);  // δv_i
    for (size_t k = 0; k < model.feet.size(); ++k) {
      const Foot& foot = model.feet[k];
      const size_t i = static_cast<size_t>(foot.body);
      // ṗ_k = R_i^W u_k with u_k = lin(X_i^fk v_i) (Eq. 37) and δR_i^W = R_i^W ψ̃_i,ang:
      //   δṗ_k = R_i^W (ψ_i,ang × u_k + lin(X_i^fk δv_i))
      const Matrix6 X_fk = detail::foot_transform(foot);
      const Vector3 u = (X_fk * data.v[i]).tail<3>();
      const Vector3 du = (X_fk * d.dv_body[i]).tail<3>();
      d.dpdot_dq.block<3, 1>(3 * static_cast<Eigen::Index>(k), column) =
          detail::rotation_of(data.X_world[i]).transpose() *
          (d.dX_motion[i].head<3>().cross(u) + du);
    }
  }
  d.direction_q.setZero();
}

void feet_force_term_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                 const VectorRef& q, const Matrix3X& f_world) {
  detail::check_derivative_data("feet_force_term_derivatives", model, derivatives);
  detail::check_q("feet_force_term_derivatives", model, data, q);
  detail::check_feet_matrix("feet_force_term_derivatives", "f_world", model, f_world);
  DerivativeData& d = derivatives;
  feet_force_terms(model, data, q, f_world);  // X_up, X_W^i and the accumulated f_i
  d.direction_v.setZero();
  for (Eigen::Index column = 0; column < model.nv; ++column) {
    detail::set_unit_direction(d.direction_q, column);
    detail::tangent_motion_pass(model, data, d);  // ψ_i
    for (Vector6& df : d.df_body) df.setZero();
    for (Vector6& df : d.df_rotor) df.setZero();  // rotors take no external wrench
    for (size_t k = 0; k < model.feet.size(); ++k) {
      const Foot& foot = model.feet[k];
      const size_t i = static_cast<size_t>(foot.body);
      // f_ext,i = (X_i^fk)ᵀ (0, R_W^i f_k) with δR_W^i = −ψ̃_i,ang R_W^i:
      //   δf_ext,i = (X_i^fk)ᵀ (0, −ψ_i,ang × R_W^i f_k)
      const Vector3 f_body = detail::rotation_of(data.X_world[i]) *
                             f_world.col(static_cast<Eigen::Index>(k));
      Vector6 df_fk;
      df_fk << Vector3::Zero(), -d.dX_motion[i].head<3>().cross(f_body);
      d.df_body[i].noalias() += detail::foot_transform(foot).transpose() * df_fk;
    }
    detail::tangent_inward_pass(model, data, d);  // δτ_e
    d.dtau_e_dq.col(column) = d.tau_column;
  }
  d.direction_q.setZero();
}

}  // namespace rbdc
