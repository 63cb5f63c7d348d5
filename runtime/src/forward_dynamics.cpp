// Paper 000 Eq. 43.
#include "rbdc/forward_dynamics.hpp"

#include <limits>

#include "argument_checks.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"

namespace rbdc {

const VectorX& forward_dynamics(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v, const VectorRef& tau, const Matrix3X& f_world) {
  detail::check_qv("forward_dynamics", model, data, q, v);
  detail::check_invertible_mass("forward_dynamics", model);
  detail::check_size("forward_dynamics", "tau", tau.size(), model.num_joints());
  detail::check_feet_matrix("forward_dynamics", "f_world", model, f_world);
  mass_matrix(model, data, q);
  quadratic_velocity_terms(model, data, q, v);
  gravity_terms(model, data, q);
  feet_force_terms(model, data, q, f_world);
  // a ← Sᵀτ + τ_e - c - g  (S_act = [0 1]: τ drives the joint rows only)
  data.a = data.tau_e - data.c - data.g;
  data.a.tail(model.num_joints()) += tau;
  // a ← M⁻¹ a by Cholesky, M = L Lᵀ, in place in the preallocated factor
  data.M_llt.compute(data.M);
  if (data.M_llt.info() != Eigen::Success) {
    data.a.setConstant(std::numeric_limits<double>::quiet_NaN());
    return data.a;
  }
  data.M_llt.solveInPlace(data.a);
  return data.a;
}

}  // namespace rbdc
