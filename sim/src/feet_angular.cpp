#include "rbdc/sim/feet_angular.hpp"

#include <stdexcept>

#include "rbdc/sim/orientation.hpp"

namespace rbdc::sim {

namespace {
// Rotation by angle about a unit axis (Rodrigues), R(a, q): child axes in parent coordinates.
Matrix3 axis_angle(const Vector3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}
}  // namespace

FeetAngularJacobian::FeetAngularJacobian(const Model& model)
    : model_(model), W_R_body_(static_cast<size_t>(model.nb), Matrix3::Identity()) {
  if (!model.floating_base) throw std::invalid_argument("FeetAngularJacobian: floating base only");
  for (int i = 1; i < model.nb; ++i)
    if (model.joints[static_cast<size_t>(i)].type != JointType::Revolute &&
        model.joints[static_cast<size_t>(i)].type != JointType::Fixed)
      throw std::invalid_argument("FeetAngularJacobian: revolute or fixed joints only");
}

void FeetAngularJacobian::compute(const double* q, MatrixX& Jw) {
  const int n_feet = static_cast<int>(model_.feet.size());
  Jw.setZero(3 * n_feet, model_.nv);
  W_R_body_[0] = rotation_from_quaternion(Eigen::Vector4d(q[3], q[4], q[5], q[6]));
  // W_R_i = W_R_λ(i) E_Tᵀ R(a, q_i): Featherstone's X_up rotation is R(a, q)ᵀ E_T (child from parent).
  for (int i = 1; i < model_.nb; ++i) {
    const Joint& joint = model_.joints[static_cast<size_t>(i)];
    Matrix3 R = W_R_body_[static_cast<size_t>(model_.parent[static_cast<size_t>(i)])] * joint.rotation.transpose();
    if (joint.type == JointType::Revolute) R = R * axis_angle(joint.axis, q[joint.q_index]);
    W_R_body_[static_cast<size_t>(i)] = R;
  }
  for (int k = 0; k < n_feet; ++k) {
    const int body = model_.feet[static_cast<size_t>(k)].body;
    // ω_B is in trunk coordinates: its columns are the trunk axes in the world.
    Jw.block<3, 3>(3 * k, 0) = W_R_body_[0];
    for (int j : model_.support[static_cast<size_t>(body)]) {
      const Joint& joint = model_.joints[static_cast<size_t>(j)];
      if (j == 0 || joint.type != JointType::Revolute) continue;
      Jw.block<3, 1>(3 * k, joint.v_index) = W_R_body_[static_cast<size_t>(j)] * joint.axis;
    }
  }
}

}  // namespace rbdc::sim
