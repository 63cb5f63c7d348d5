// Derivatives of forward dynamics (Eq. 43) from those of the equation of motion (Eq. 30):
// differentiating M(q) a + c(q, v) + g(q) − Jᵀ(q) f = Sᵀτ at the forward-dynamics solution a gives
//   ∂a/∂q = −M⁻¹ (∂τ/∂q − ∂(Jᵀf)/∂q),  ∂a/∂v = −M⁻¹ ∂τ/∂v,  ∂a/∂τ = M⁻¹Sᵀ,  ∂a/∂f = M⁻¹Jᵀ,
// with ∂τ/∂(q, v) the inverse-dynamics derivatives at (q, v, a) (the ∂M/∂q · a term is inside them).
#include <limits>

#include "argument_checks.hpp"
#include "derivative_passes.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

void forward_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                  const Matrix3X& f_world) {
  detail::check_derivative_data("forward_dynamics_derivatives", model, derivatives);
  detail::check_qv("forward_dynamics_derivatives", model, data, q, v);
  detail::check_invertible_mass("forward_dynamics_derivatives", model);
  detail::check_size("forward_dynamics_derivatives", "tau", tau.size(), model.num_joints());
  detail::check_feet_matrix("forward_dynamics_derivatives", "f_world", model, f_world);
  DerivativeData& d = derivatives;
  // a = M⁻¹(Sᵀτ + Jᵀf − c − g), leaving the Cholesky factor of M in data.M_llt
  forward_dynamics(model, data, q, v, tau, f_world);
  if (data.M_llt.info() != Eigen::Success) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (MatrixX* m : {&d.da_dq, &d.da_dv, &d.da_dtau, &d.da_df}) m->setConstant(nan);
    return;
  }
  // ∂(Jᵀf)/∂q, then ∂τ/∂(q, v) of the RNEA at (q, v, a); neither touches data.a or data.M_llt
  feet_force_term_derivatives(model, data, d, q, f_world);
  inverse_dynamics_derivatives(model, data, d, q, v, data.a);
  // ∂a/∂q = M⁻¹ (∂(Jᵀf)/∂q − ∂τ/∂q)
  d.da_dq = d.dtau_e_dq - d.dtau_dq;
  detail::solve_with_mass_matrix(data, d.da_dq);
  // ∂a/∂v = −M⁻¹ ∂τ/∂v
  d.da_dv = -d.dtau_dv;
  detail::solve_with_mass_matrix(data, d.da_dv);
  // ∂a/∂τ = M⁻¹Sᵀ: Sᵀ selects the joint rows (the trunk is unactuated)
  d.da_dtau.setZero();
  d.da_dtau.bottomRows(model.num_joints()).setIdentity();
  detail::solve_with_mass_matrix(data, d.da_dtau);
  // ∂a/∂f = M⁻¹Jᵀ, columns 3k … 3k+2 for foot k
  d.da_df = feet_jacobian(model, data, q).transpose();
  detail::solve_with_mass_matrix(data, d.da_df);
}

}  // namespace rbdc
