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

/// X_i^F (Eq. 5): body i's coordinates to frame F's, from the frame's constant pose.
inline Matrix6 frame_transform(const Frame& frame) {
  return motion_transform(frame.rotation, frame.translation);
}

/// Rotation block R_A^B of a motion transform X_A^B.
inline Matrix3 rotation_of(const Matrix6& X) { return X.topLeftCorner<3, 3>(); }

/// Body i's origin p_i in the world, read from X_W^i's lower-left block -R_W^i p̃_i (Eq. 18).
inline Vector3 origin_of(const Matrix6& X_W_i) {
  const Matrix3 p_tilde = -rotation_of(X_W_i).transpose() * X_W_i.bottomLeftCorner<3, 3>();
  return {p_tilde(2, 1), p_tilde(0, 2), p_tilde(1, 0)};
}

/// Body i's Jacobian in body coordinates, J_i = [X_j^i S_j]_{j ∈ κ(i)} (paper 000 Eq. B3), into J
/// (6 × nv, other columns zero), after kinematics(). κ(i) is walked from i to the root so that
/// X_λ(j)^i = X_j^i X_λ(j)^j comes one product at a time; a floating base's joint 0 has S_0 = 1₆,
/// so its block is X_0^i itself.
inline void body_jacobian(const Model& model, const Data& data, int i, Matrix6X& J) {
  J.setZero();
  Matrix6 X_j_to_i = Matrix6::Identity();  // X_j^i, starting at j = i
  for (int j = i; j != 0; j = model.parent[static_cast<size_t>(j)]) {
    const size_t uj = static_cast<size_t>(j);
    J.col(model.joints[uj].v_index) = X_j_to_i * model.motion_subspace[uj];
    X_j_to_i = X_j_to_i * data.X_up[uj];
  }
  if (model.floating_base) J.leftCols<6>() = X_j_to_i;
}

/// v × m without forming crm(v): (ω × m_ω, ω × m_v + v_O × m_ω). Exactly zero when m is v itself
/// (each 3-D cross product of a vector with itself is), where the 6 × 6 product leaves round-off; so
/// a first joint on a fixed base has J̇v = 0 exactly, as the generated code has it.
inline Vector6 cross_motion(const Vector6& v, const Vector6& m) {
  Vector6 out;
  out << v.head<3>().cross(m.head<3>()), v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return out;
}

/// The velocity-product accelerations a_i at a = 0 into data.a_body, after kinematics(q, v):
///   a_0 ← (0, -ω_0 × v_0)  (a floating trunk's spatial acceleration when a[0:6] = 0, as in Alg. 2)
///   a_i ← X_λ(i)^i a_λ(i) + v_i × S_i q̇_i                                          (Eq. 19)
inline void bias_accelerations(const Model& model, Data& data, const VectorRef& v) {
  data.a_body[0].setZero();
  if (model.floating_base) data.a_body[0].tail<3>() = -data.v[0].head<3>().cross(data.v[0].tail<3>());
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    data.a_body[ui] = data.X_up[ui] * data.a_body[j] +
                      cross_motion(data.v[ui], model.motion_subspace[ui] * v[model.joints[ui].v_index]);
  }
}

/// Classical acceleration (ω̇; p̈) of a point frame from its spatial acceleration a and velocity
/// v = (ω; v_O), both in its own coordinates: p̈ = a_O + ω × v_O (Featherstone, RBDA Eq. 2.38).
inline Vector6 classical_acceleration(const Vector6& a, const Vector6& v) {
  Vector6 classical = a;
  classical.tail<3>() += v.head<3>().cross(v.tail<3>());
  return classical;
}

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
