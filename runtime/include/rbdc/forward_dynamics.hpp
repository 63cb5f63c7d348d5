// Forward dynamics from the equation of motion (paper 000 Eq. 30) by Cholesky factorisation.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// Eq. 43: a = M⁻¹(Sᵀτ + τ_e - c - g), with M from Alg. 5, c, g from Algs. 2-3 and τ_e from the
/// foot forces (Alg. 4). q: nq, v: nv, tau: n_joints (actuated joint efforts), f_world: 3 × n_feet
/// world forces on the foot points. If M is not positive definite (e.g. NaN input) every entry of
/// the result is NaN. Returns data.a.
const VectorX& forward_dynamics(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v, const VectorRef& tau, const Matrix3X& f_world);

}  // namespace rbdc
