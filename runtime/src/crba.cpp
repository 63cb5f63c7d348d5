// Paper 000 Alg. 5 (Eqs. 26-29).
#include "rbdc/crba.hpp"

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"

namespace rbdc {

const MatrixX& mass_matrix(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("mass_matrix", model, data, q);
  kinematics(model, data, q);
  MatrixX& H = data.M;
  const auto S = [&](int i) -> const Vector6& { return model.motion_subspace[static_cast<size_t>(i)]; };
  const auto X_up = [&](int i) -> const Matrix6& { return data.X_up[static_cast<size_t>(i)]; };
  const auto lambda = [&](int i) { return model.parent[static_cast<size_t>(i)]; };
  const auto col = [&](int i) { return model.joints[static_cast<size_t>(i)].v_index; };

  // H ← 0
  H.setZero();
  // for i = 0 … nb-1: I_ci ← I_i
  for (int i = 0; i < model.nb; ++i) data.Ic[static_cast<size_t>(i)] = model.inertia[static_cast<size_t>(i)];
  // for i = nb-1 … 1
  for (int i = model.nb - 1; i >= 1; --i) {
    const Matrix6& Ici = data.Ic[static_cast<size_t>(i)];
    //   I_cj ← I_cj + (X_j^i)ᵀ I_ci X_j^i,  j = λ(i)          (Eq. 26)
    data.Ic[static_cast<size_t>(lambda(i))].noalias() += X_up(i).transpose() * Ici * X_up(i);
    //   F_i ← I_ci S_i                                       (Eq. 28)
    const Vector6 F_i = Ici * S(i);
    //   H_ii ← S_iᵀ F_i
    H(col(i), col(i)) = S(i).dot(F_i);
    //   j ← i; while λ(j) ≠ 0: F_i ← (X_λ(j)^j)ᵀ F_i; j ← λ(j); H_ij ← F_iᵀ S_j; H_ji ← H_ijᵀ (Eq. 27)
    Vector6 F = F_i;  // F_i carried towards the root, one body at a time
    for (int j = i; lambda(j) != 0;) {
      F = X_up(j).transpose() * F;
      j = lambda(j);
      H(col(i), col(j)) = F.dot(S(j));
      H(col(j), col(i)) = H(col(i), col(j));
    }
    //   F_i ← (X_0^i)ᵀ F_i: the trunk wrench that supports a unit q̈_i (the block column F of Eq. 29)
    if (model.floating_base) {
      const Vector6 F_i0 = data.X_root[static_cast<size_t>(i)].transpose() * F_i;
      H.block<6, 1>(0, col(i)) = F_i0;
      H.block<1, 6>(col(i), 0) = F_i0.transpose();
    }
  }
  // Floating base: the trunk block is the composite inertia of the whole tree, I_c0 (Eq. 29),
  // symmetrised so that M is exactly symmetric (the sums above leave round-off asymmetry).
  if (model.floating_base) H.topLeftCorner<6, 6>() = 0.5 * (data.Ic[0] + data.Ic[0].transpose());
  return H;
}

}  // namespace rbdc
