#include "rbdc/sim/orientation.hpp"

#include <algorithm>
#include <cmath>

namespace rbdc::sim {

Matrix3 rotation_from_zyx(const Vector3& xi) {
  return (Eigen::AngleAxisd(xi[0], Vector3::UnitZ()) * Eigen::AngleAxisd(xi[1], Vector3::UnitY()) *
          Eigen::AngleAxisd(xi[2], Vector3::UnitX()))
      .toRotationMatrix();
}

Vector3 zyx_from_rotation(const Matrix3& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  return {std::atan2(R(1, 0), R(0, 0)), pitch, std::atan2(R(2, 1), R(2, 2))};
}

Matrix3 euler_rate_matrix(const Vector3& xi) {
  const double cpsi = std::cos(xi[0]), spsi = std::sin(xi[0]);
  const double cth = std::cos(xi[1]), sth = std::sin(xi[1]);
  Matrix3 G;
  G << 0, -spsi, cth * cpsi,  //
      0, cpsi, cth * spsi,    //
      1, 0, -sth;
  return G;
}

Vector3 euler_rates(const Vector3& xi, const Vector3& omega_W) {
  // Closed form of G⁻¹ (Eq. 42): divide by cos θ instead of a general 3x3 solve.
  const double cpsi = std::cos(xi[0]), spsi = std::sin(xi[0]);
  const double cth = std::cos(xi[1]), tth = std::tan(xi[1]);
  const double roll_rate = (cpsi * omega_W.x() + spsi * omega_W.y()) / cth;
  return {omega_W.z() + tth * (cpsi * omega_W.x() + spsi * omega_W.y()),
          -spsi * omega_W.x() + cpsi * omega_W.y(), roll_rate};
}

Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Vector3& w) {
  return 0.5 * Eigen::Vector4d(-q[1] * w.x() - q[2] * w.y() - q[3] * w.z(),
                               q[0] * w.x() + q[2] * w.z() - q[3] * w.y(),
                               q[0] * w.y() + q[3] * w.x() - q[1] * w.z(),
                               q[0] * w.z() + q[1] * w.y() - q[2] * w.x());
}

Matrix3 rotation_from_quaternion(const Eigen::Vector4d& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

Eigen::Vector4d quaternion_from_rotation(const Matrix3& R) {
  const Eigen::Quaterniond q(R);
  return {q.w(), q.x(), q.y(), q.z()};
}

}  // namespace rbdc::sim
