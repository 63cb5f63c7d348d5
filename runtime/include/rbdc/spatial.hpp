// Spatial algebra on dense 6x6 Eigen matrices, in the conventions of docs/conventions.md
// (Featherstone ordering: angular first). The runtime is the readable reference, so it uses
// plain dense arithmetic; the generator is where structure gets exploited.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rbdc {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using VectorX = Eigen::VectorXd;
using MatrixX = Eigen::MatrixXd;

/// Skew-symmetric matrix r̃ with r̃ x = r × x (paper 000 App. A).
inline Matrix3 skew(const Vector3& r) {
  Matrix3 s;
  s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return s;
}

/// Motion transform X_A^B = [E 0; -E r̃ E] (Eq. 5): E = R_A^B (A → B coordinates),
/// r = origin of B expressed in A.
inline Matrix6 motion_transform(const Matrix3& E, const Vector3& r) {
  Matrix6 X = Matrix6::Zero();
  X.topLeftCorner<3, 3>() = E;
  X.bottomRightCorner<3, 3>() = E;
  X.bottomLeftCorner<3, 3>() = -E * skew(r);
  return X;
}

/// Force transform X*_A^B = (X_A^B)^{-T} = [E -E r̃; 0 E] (Eq. 7-8).
inline Matrix6 force_transform(const Matrix3& E, const Vector3& r) {
  Matrix6 X = Matrix6::Zero();
  X.topLeftCorner<3, 3>() = E;
  X.bottomRightCorner<3, 3>() = E;
  X.topRightCorner<3, 3>() = -E * skew(r);
  return X;
}

/// Motion cross product matrix v× (twist cross product "*" of paper 000 App. A).
inline Matrix6 crm(const Vector6& v) {
  Matrix6 m = Matrix6::Zero();
  const Matrix3 w = skew(v.head<3>());
  m.topLeftCorner<3, 3>() = w;
  m.bottomRightCorner<3, 3>() = w;
  m.bottomLeftCorner<3, 3>() = skew(v.tail<3>());
  return m;
}

/// Force cross product matrix v×* = -(v×)ᵀ (wrench cross product "⊗" of paper 000 App. A).
inline Matrix6 crf(const Vector6& v) { return -crm(v).transpose(); }

/// Spatial inertia at the body origin from mass, COM and rotational inertia about the COM.
inline Matrix6 spatial_inertia(double mass, const Vector3& com, const Matrix3& inertia_com) {
  Matrix6 I;
  const Matrix3 c = skew(com);
  I.topLeftCorner<3, 3>() = inertia_com + mass * c * c.transpose();
  I.topRightCorner<3, 3>() = mass * c;
  I.bottomLeftCorner<3, 3>() = mass * c.transpose();
  I.bottomRightCorner<3, 3>() = mass * Matrix3::Identity();
  return I;
}

/// Coordinate (passive) rotation for angle q about a unit axis: rot(axis, q)ᵀ.
inline Matrix3 coordinate_rotation(const Vector3& axis, double q) {
  return Eigen::AngleAxisd(q, axis).toRotationMatrix().transpose();
}

}  // namespace rbdc
