// Paper 000 Alg. 5 (Eqs. 26-29).
#include "rbdc/crba.hpp"

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"

namespace rbdc {

namespace {

// Rotor i's part of column i (rotors.hpp): its spin S_rot q̈_i needs F_r = I_rot S_rot, so
// H_ii += S_rotᵀ F_r; F_r, moved onto the carrier λ(i) by X_rotᵀ and towards the root like F_i
// (Eq. 27), gives H_ij += F_rᵀ S_j for j ∈ κ(λ(i)) and the trunk block column (Eq. 29).
void add_rotor_column(const Model& model, Data& data, int i) {
  const size_t ui = static_cast<size_t>(i);
  MatrixX& H = data.M;
  const int ci = model.joints[ui].v_index;
  const Vector6 F_r = model.rotor_inertia[ui] * model.rotor_subspace[ui];
  H(ci, ci) += model.rotor_subspace[ui].dot(F_r);
  Vector6 F = model.X_rotor[ui].transpose() * F_r;  // at the carrier λ(i)
  int j = model.parent[ui];
  for (; j != 0; j = model.parent[static_cast<size_t>(j)]) {
    const size_t uj = static_cast<size_t>(j);
    const int cj = model.joints[uj].v_index;
    H(ci, cj) += F.dot(model.motion_subspace[uj]);
    H(cj, ci) = H(ci, cj);
    F = data.X_up[uj].transpose() * F;
  }
  if (model.floating_base) {
    H.block<6, 1>(0, ci) += F;
    H.block<1, 6>(ci, 0) += F.transpose();
  }
}

}  // namespace

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
  //   with rotors: I_cλ(i) ← I_cλ(i) + X_rot,iᵀ I_rot,i X_rot,i (the rotor rides on λ(i))
  if (model.has_rotors) {
    for (int i = 1; i < model.nb; ++i) {
      const size_t ui = static_cast<size_t>(i);
      data.Ic[static_cast<size_t>(lambda(i))].noalias() +=
          model.X_rotor[ui].transpose() * model.rotor_inertia[ui] * model.X_rotor[ui];
    }
  }
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
    if (model.has_rotors) add_rotor_column(model, data, i);
    //   armature: H_ii ← H_ii + armature_i (reflected inertia, diagonal only)
    H(col(i), col(i)) += model.joints[static_cast<size_t>(i)].armature;
  }
  // Floating base: the trunk block is the composite inertia of the whole tree, I_c0 (Eq. 29),
  // symmetrised so that M is exactly symmetric (the sums above leave round-off asymmetry).
  if (model.floating_base) H.topLeftCorner<6, 6>() = 0.5 * (data.Ic[0] + data.Ic[0].transpose());
  return H;
}

}  // namespace rbdc
