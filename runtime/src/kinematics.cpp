// Paper 000 Section 3 (Alg. 1, Eqs. 9-18) and Eq. 37.
#include "rbdc/kinematics.hpp"

#include "argument_checks.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

using detail::foot_transform;
using detail::rotation_of;

namespace {

// Eq. 14: X_W^0 from the trunk position p_W and orientation quaternion (w, x, y, z).
Matrix6 trunk_world_transform(const Model& model, const VectorRef& q) {
  if (!model.floating_base) return Matrix6::Identity();
  const Eigen::Quaterniond orientation(q[3], q[4], q[5], q[6]);
  const Matrix3 world_R_trunk = orientation.normalized().toRotationMatrix();  // R_0^W
  return motion_transform(world_R_trunk.transpose(), q.head<3>());
}

}  // namespace

void kinematics(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("kinematics", model, data, q);
  data.X_world[0] = trunk_world_transform(model, q);
  // for i = 1 … nb-1
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const Joint& joint = model.joints[ui];
    //   j ← λ(i)
    const size_t j = static_cast<size_t>(model.parent[ui]);
    //   X_j^i ← X_{j,i}^i X_j^{j,i}                       (Eqs. 9-11)
    data.X_up[ui] = detail::joint_transform(joint, q[joint.q_index]) * model.X_tree[ui];
    //   X_0^i ← X_j^i X_0^j        (X_0^0 = 1 covers j = 0)  (Eq. 12)
    data.X_root[ui] = data.X_up[ui] * data.X_root[j];
  }
}

void kinematics(const Model& model, Data& data, const VectorRef& q, const VectorRef& v) {
  detail::check_qv("kinematics", model, data, q, v);
  kinematics(model, data, q);
  // v_0: the trunk twist in trunk coordinates (floating base) or rest (fixed base)
  data.v[0] = model.floating_base ? Vector6(v.head<6>()) : Vector6::Zero();
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    //   v_i ← X_j^i v_j + S_i q̇_i                         (Eq. 13)
    data.v[ui] = data.X_up[ui] * data.v[j] +
                 model.motion_subspace[ui] * v[model.joints[ui].v_index];
  }
}

const std::vector<Matrix6>& world_transforms(const Model& model, Data& data, const VectorRef& q) {
  kinematics(model, data, q);
  // X_W^i = X_0^i X_W^0                                  (Eq. 15)
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    data.X_world[ui] = data.X_root[ui] * data.X_world[0];
  }
  return data.X_world;
}

const Matrix3X& feet_positions(const Model& model, Data& data, const VectorRef& q) {
  world_transforms(model, data, q);
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Foot& foot = model.feet[k];
    // X_W^fk = X_i^fk X_W^i, i = φ(k)                     (Eqs. 16-17)
    const Matrix6 X_W_fk = foot_transform(foot) * data.X_world[static_cast<size_t>(foot.body)];
    const Matrix3 R_W_fk = rotation_of(X_W_fk);
    // r̃_{O_W O_fk}^W = -(R_W^fk)ᵀ (-R_W^fk r̃^W), read from the lower-left block (Eq. 18)
    const Matrix3 r_tilde = -R_W_fk.transpose() * X_W_fk.bottomLeftCorner<3, 3>();
    data.feet_position.col(static_cast<Eigen::Index>(k)) =
        Vector3(r_tilde(2, 1), r_tilde(0, 2), r_tilde(1, 0));
    data.world_R_foot[k] = R_W_fk.transpose();
  }
  return data.feet_position;
}

const Matrix3X& feet_velocities(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v) {
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Foot& foot = model.feet[k];
    const size_t i = static_cast<size_t>(foot.body);
    // v_fk^W = diag(R_fk^W, R_fk^W) X_i^fk v_i; keep the linear part     (Eq. 37)
    const Vector6 v_fk = foot_transform(foot) * data.v[i];
    data.feet_velocity.col(static_cast<Eigen::Index>(k)) =
        rotation_of(data.X_world[i]).transpose() * v_fk.tail<3>();
  }
  return data.feet_velocity;
}

const Matrix3X& feet_bias_accelerations(const Model& model, Data& data, const VectorRef& q,
                                        const VectorRef& v) {
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  // a_i at a = 0 (Eq. 19)
  detail::bias_accelerations(model, data, v);
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Foot& foot = model.feet[k];
    const size_t i = static_cast<size_t>(foot.body);
    // Classical acceleration of the foot point: spatial acceleration there plus ω × v.
    const Matrix6 X_fk = foot_transform(foot);
    const Vector6 a_fk = X_fk * data.a_body[i];
    const Vector6 v_fk = X_fk * data.v[i];
    data.feet_bias_acceleration.col(static_cast<Eigen::Index>(k)) =
        rotation_of(data.X_world[i]).transpose() * detail::classical_acceleration(a_fk, v_fk).tail<3>();
  }
  return data.feet_bias_acceleration;
}

}  // namespace rbdc
