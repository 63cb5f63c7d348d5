// Analytic derivatives of the dynamics (issue 12): inverse dynamics (RNEA), bias and gravity terms,
// forward dynamics and the feet terms, with respect to q on the manifold (tangent δ applied as
// q ⊕ δ, rbdc/manifold.hpp) and plainly with respect to v, τ and the foot forces.
// Method and equations: docs/runtime.md ("Derivatives"); conventions: docs/conventions.md.
#pragma once

#include <vector>

#include "rbdc/data.hpp"
#include "rbdc/manifold.hpp"

namespace rbdc {

/// Results and workspace of the derivative algorithms. Every matrix is column-major and allocated
/// in the constructor, so no call below touches the heap. Columns of ∂/∂q and ∂/∂v are ordered
/// like v: (δθ, δp, joints) for a floating base.
struct DerivativeData {
  explicit DerivativeData(const Model& model);

  MatrixX dtau_dq;    ///< ∂τ/∂q of inverse dynamics (nv × nv); ∂τ/∂a is M
  MatrixX dtau_dv;    ///< ∂τ/∂v of inverse dynamics (nv × nv)
  MatrixX dbias_dq;   ///< ∂(c + g)/∂q (nv × nv)
  MatrixX dbias_dv;   ///< ∂(c + g)/∂v (nv × nv)
  MatrixX dg_dq;      ///< ∂g/∂q (nv × nv)
  MatrixX da_dq;      ///< ∂a/∂q of forward dynamics (nv × nv)
  MatrixX da_dv;      ///< ∂a/∂v of forward dynamics (nv × nv)
  MatrixX da_dtau;    ///< ∂a/∂τ = M⁻¹Sᵀ (nv × n_joints)
  MatrixX da_df;      ///< ∂a/∂f = M⁻¹Jᵀ (nv × 3·n_feet); column 3k + c: foot k, axis c
  MatrixX dpdot_dq;   ///< ∂(world foot velocities, foot-major rows)/∂q (3·n_feet × nv)
  MatrixX dtau_e_dq;  ///< ∂(Jᵀf)/∂q at fixed world foot forces f (nv × nv)

  // --- Workspace of one tangent (directional-derivative) pass, index = body ---------------------
  std::vector<Vector6> dX_motion;  ///< ψ_i: the configuration tangent as a body twist
  std::vector<Vector6> dv_body;    ///< δv_i
  std::vector<Vector6> da_body;    ///< δa_i
  std::vector<Vector6> df_body;    ///< δf_i
  std::vector<Vector6> df_rotor;   ///< δf_rot,i of joint i's rotor (stays zero without rotors)
  VectorX direction_q;             ///< δq of the current pass (nv), a unit vector
  VectorX direction_v;             ///< δv of the current pass (nv), a unit vector
  VectorX zero_nv;                 ///< v = 0 or a = 0 for the bias and gravity derivatives
  VectorX tau_column;              ///< δτ of the current pass (nv)
};

/// ∂τ/∂q, ∂τ/∂v of τ = inverse_dynamics(q, v, a) → dtau_dq, dtau_dv. q: nq, v: nv, a: nv.
void inverse_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  const VectorRef& q, const VectorRef& v, const VectorRef& a);

/// ∂(c + g)/∂q, ∂(c + g)/∂v (inverse dynamics at a = 0) → dbias_dq, dbias_dv. q: nq, v: nv.
void bias_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                      const VectorRef& q, const VectorRef& v);

/// ∂g/∂q → dg_dq. q: nq.
void gravity_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                         const VectorRef& q);

/// Derivatives of a = forward_dynamics(q, v, tau, f_world) → da_dq, da_dv, da_dtau, da_df:
/// ∂a/∂(q, v) = −M⁻¹ (∂τ/∂(q, v) − ∂(Jᵀf)/∂(q, 0)) at (q, v, a), ∂a/∂τ = M⁻¹Sᵀ, ∂a/∂f = M⁻¹Jᵀ.
/// Also leaves dtau_dq, dtau_dv (at that a) and dtau_e_dq filled, data.a = a and data.M_llt the
/// factor of M. q: nq, v: nv, tau: n_joints, f_world: 3 × n_feet. If M is not positive definite
/// every entry of the four results is NaN.
void forward_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                  const Matrix3X& f_world);

/// ∂(feet_velocities(q, v), stacked foot-major)/∂q → dpdot_dq. q: nq, v: nv.
void feet_velocity_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                               const VectorRef& q, const VectorRef& v);

/// ∂(feet_force_terms(q, f_world))/∂q = ∂(Jᵀf)/∂q at fixed world forces → dtau_e_dq.
/// q: nq, f_world: 3 × n_feet.
void feet_force_term_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                 const VectorRef& q, const Matrix3X& f_world);

}  // namespace rbdc
