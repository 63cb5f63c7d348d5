// Full recursive Newton-Euler inverse dynamics (paper 000 Eqs. 19-23 with the joint
// accelerations included), independent of the mass matrix.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// τ = M(q) a + c(q, v) + g(q) by one RNEA. q: nq, v: nv, a: nv (floating base: a[0:6] =
/// (ω̇_B, R_W^0 p̈_W), see docs/conventions.md). No external forces. Returns data.tau.
const VectorX& inverse_dynamics(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v, const VectorRef& a);

}  // namespace rbdc
