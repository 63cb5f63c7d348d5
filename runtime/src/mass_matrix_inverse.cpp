// M⁻¹ through the Cholesky factor of M (Alg. 5 then Eq. 43's factorisation).
#include <limits>

#include "argument_checks.hpp"
#include "rbdc/crba.hpp"

namespace rbdc {

const MatrixX& mass_matrix_inverse(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("mass_matrix_inverse", model, data, q);
  detail::check_invertible_mass("mass_matrix_inverse", model);
  // M = L Lᵀ in the preallocated factor
  data.M_llt.compute(mass_matrix(model, data, q));
  if (data.M_llt.info() != Eigen::Success) {
    data.M_inverse.setConstant(std::numeric_limits<double>::quiet_NaN());
    return data.M_inverse;
  }
  // M⁻¹ e_k = L⁻ᵀ (L⁻¹ e_k), column by column (a vector solve needs no workspace)
  data.M_inverse.setIdentity();
  for (Eigen::Index k = 0; k < model.nv; ++k) {
    auto column = data.M_inverse.col(k);
    data.M_llt.solveInPlace(column);
  }
  return data.M_inverse;
}

}  // namespace rbdc
