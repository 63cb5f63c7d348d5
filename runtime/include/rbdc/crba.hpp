// Joint-space inertia matrix by the composite-rigid-body algorithm (paper 000 Section 4.4).
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// Alg. 5 (Eqs. 26-29): M(q), nv × nv, full symmetric. For a floating base the top-left 6 × 6
/// block is I_c0 and the top-right 6 × n block is F (Eq. 29), both in trunk coordinates.
/// q: nq. Also leaves the composite inertias in data.Ic. Returns data.M.
const MatrixX& mass_matrix(const Model& model, Data& data, const VectorRef& q);

}  // namespace rbdc
