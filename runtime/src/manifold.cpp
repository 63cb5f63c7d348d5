// The manifold step q ⊕ δ and its coordinate Jacobian (docs/conventions.md, "Derivatives on the
// manifold").
#include "rbdc/manifold.hpp"

#include <stdexcept>
#include <string>

#include "argument_checks.hpp"

namespace rbdc {

namespace {

Eigen::Quaterniond trunk_orientation(const VectorRef& q) {
  return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
}

/// exp(θ^) as a unit quaternion (exact for every angle, the identity at θ = 0).
Eigen::Quaterniond rotation_exp(const Vector3& theta) {
  const double angle = theta.norm();
  if (angle == 0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle));
}

/// ½ q ⊗ (0, e_k) for k = 0, 1, 2 as the columns of a 4 × 3 matrix (rows w, x, y, z):
/// (w, u) ⊗ (0, e) = (−u·e, w e + u × e).
Eigen::Matrix<double, 4, 3> quaternion_tangents(const Eigen::Quaterniond& quat) {
  Eigen::Matrix<double, 4, 3> G;
  const Vector3 u = quat.vec();
  G.row(0) = -0.5 * u.transpose();
  G.bottomRows<3>() = 0.5 * (quat.w() * Matrix3::Identity() + skew(u));
  return G;
}

void check_matrix(const char* function, const char* argument, const MatrixX& m, Eigen::Index rows,
                  Eigen::Index cols) {
  if (m.rows() != rows || m.cols() != cols) {
    throw std::invalid_argument(std::string("rbdc::") + function + ": " + argument + " is " +
                                std::to_string(m.rows()) + " × " + std::to_string(m.cols()) +
                                ", expected " + std::to_string(rows) + " × " +
                                std::to_string(cols));
  }
}

}  // namespace

void integrate(const Model& model, const VectorRef& q, const VectorRef& delta,
               Eigen::Ref<VectorX> q_out) {
  detail::check_size("integrate", "q", q.size(), model.nq);
  detail::check_size("integrate", "delta", delta.size(), model.nv);
  detail::check_size("integrate", "q_out", q_out.size(), model.nq);
  const int joints = model.num_joints();
  // q_j' = q_j + δq_j (elementwise, so q_out may alias q)
  q_out.tail(joints) = q.tail(joints) + delta.tail(joints);
  if (!model.floating_base) return;
  const Eigen::Quaterniond orientation = trunk_orientation(q);
  // p' = p + R δp, R' = R exp(δθ^); read everything from q before writing q_out.
  const Vector3 position = q.head<3>() + orientation.toRotationMatrix() * delta.segment<3>(3);
  const Eigen::Quaterniond next = (orientation * rotation_exp(delta.head<3>())).normalized();
  q_out.head<3>() = position;
  q_out.segment<4>(3) << next.w(), next.x(), next.y(), next.z();
}

void tangent_map(const Model& model, const VectorRef& q, MatrixX& T) {
  detail::check_size("tangent_map", "q", q.size(), model.nq);
  check_matrix("tangent_map", "T", T, model.nq, model.nv);
  T.setZero();
  const int joints = model.num_joints();
  T.bottomRightCorner(joints, joints).setIdentity();
  if (!model.floating_base) return;
  const Eigen::Quaterniond orientation = trunk_orientation(q);
  // ∂p'/∂δp = R; ∂q_quat'/∂δθ_k = ½ q_quat ⊗ (0, e_k)
  T.block<3, 3>(0, 3) = orientation.toRotationMatrix();
  T.block<4, 3>(3, 0) = quaternion_tangents(orientation);
}

void tangent_map_inverse(const Model& model, const VectorRef& q, MatrixX& T_inverse) {
  detail::check_size("tangent_map_inverse", "q", q.size(), model.nq);
  check_matrix("tangent_map_inverse", "T_inverse", T_inverse, model.nv, model.nq);
  T_inverse.setZero();
  const int joints = model.num_joints();
  T_inverse.bottomRightCorner(joints, joints).setIdentity();
  if (!model.floating_base) return;
  const Eigen::Quaterniond orientation = trunk_orientation(q);
  // The columns of G = ½ q ⊗ (0, e_k) are orthogonal with norm ½ (and orthogonal to q):
  // G⁺ = (GᵀG)⁻¹Gᵀ = 4 Gᵀ. Rᵀ inverts the position block.
  T_inverse.block<3, 3>(3, 0) = orientation.toRotationMatrix().transpose();
  T_inverse.block<3, 4>(0, 3) = 4.0 * quaternion_tangents(orientation).transpose();
}

void swap_trunk_angular_linear(const Model& model, MatrixX& m, bool rows) {
  if (!model.floating_base) return;
  const Eigen::Index n = rows ? m.rows() : m.cols();
  if (n < 6) {
    throw std::invalid_argument(std::string("rbdc::swap_trunk_angular_linear: the matrix has ") +
                                std::to_string(n) + (rows ? " rows" : " columns") +
                                ", expected at least 6 (a floating base's velocity block)");
  }
  for (Eigen::Index k = 0; k < 3; ++k) {
    if (rows) {
      m.row(k).swap(m.row(k + 3));
    } else {
      m.col(k).swap(m.col(k + 3));
    }
  }
}

}  // namespace rbdc
