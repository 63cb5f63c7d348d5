// Small pieces shared by several runtime algorithms: the joint transform X_J(q), the foot
// transform X_i^fk (paper 000 Eq. 16), the solve with the factor of M and the inward force pass
// common to Algs. 2-4 and the RNEA.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc::detail {

/// X_J(q): revolute joints rotate about the axis, prismatic joints translate along it.
inline Matrix6 joint_transform(const Joint& joint, double q) {
  if (joint.type == JointType::Prismatic) {
    return motion_transform(Matrix3::Identity(), q * joint.axis);
  }
  return motion_transform(coordinate_rotation(joint.axis, q), Vector3::Zero());
}

/// X_i^fk (Eq. 16): pure translation from body i's origin to the foot point.
inline Matrix6 foot_transform(const Foot& foot) {
  return motion_transform(Matrix3::Identity(), foot.offset);
}

/// Rotation block R_A^B of a motion transform X_A^B.
inline Matrix3 rotation_of(const Matrix6& X) { return X.topLeftCorner<3, 3>(); }

/// X ← M⁻¹ X, column by column with the factor in data.M_llt (vector solves need no scratch).
inline void solve_with_mass_matrix(const Data& data, MatrixX& X) {
  for (Eigen::Index k = 0; k < X.cols(); ++k) {
    auto column = X.col(k);
    data.M_llt.solveInPlace(column);
  }
}

/// The inward pass shared by Algs. 2, 3 and 4 (and the full RNEA), over data.f_body:
///   for i = nb-1 … 1:  out_i ← S_iᵀ f_i;  f_λ(i) ← f_λ(i) + (X_λ(i)^i)ᵀ f_i
///   out_0 ← S_0ᵀ f_0   (S_0 = 1₆ for a floating base; a fixed base has no entries)
/// With rotors, rotor i's wrench data.f_rotor[i] also drives its joint and loads its carrier:
///   out_i += S_rotᵀ f_rot,i;  f_λ(i) += X_rotᵀ f_rot,i
inline void inward_force_pass(const Model& model, Data& data, VectorX& out) {
  for (int i = model.nb - 1; i >= 1; --i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    out[model.joints[ui].v_index] = model.motion_subspace[ui].dot(data.f_body[ui]);
    data.f_body[j].noalias() += data.X_up[ui].transpose() * data.f_body[ui];
    if (model.has_rotors) {
      out[model.joints[ui].v_index] += model.rotor_subspace[ui].dot(data.f_rotor[ui]);
      data.f_body[j].noalias() += model.X_rotor[ui].transpose() * data.f_rotor[ui];
    }
  }
  if (model.floating_base) out.head<6>() = data.f_body[0];
}

}  // namespace rbdc::detail
