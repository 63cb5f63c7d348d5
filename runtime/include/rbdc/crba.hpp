// Joint-space inertia matrix by the composite-rigid-body algorithm (paper 000 Section 4.4).
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// Alg. 5 (Eqs. 26-29): M(q), nv × nv, full symmetric. For a floating base the top-left 6 × 6
/// block is I_c0 and the top-right 6 × n block is F (Eq. 29), both in trunk coordinates.
/// q: nq. Also leaves the composite inertias in data.Ic. Returns data.M.
const MatrixX& mass_matrix(const Model& model, Data& data, const VectorRef& q);

/// M⁻¹(q), nv × nv, through the Cholesky factor of Alg. 5's M: M = L Lᵀ (data.M_llt), then
/// M⁻¹ = L⁻ᵀ L⁻¹ by solving M X = 1 column by column in place (allocation-free). An M that is not
/// positive definite (a massless chain) gives a NaN-filled result, as forward_dynamics does.
/// q: nq. Returns data.M_inverse.
const MatrixX& mass_matrix_inverse(const Model& model, Data& data, const VectorRef& q);

}  // namespace rbdc
