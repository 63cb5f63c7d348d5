// Trunk orientation helpers: ZYX Euler angles ξ = (ψ, θ, φ) (yaw, pitch, roll) with the rate
// conversion of paper 000 Eqs. 41-42, and unit quaternions (w, x, y, z).
#pragma once

#include "rbdc/spatial.hpp"

namespace rbdc::sim {

/// R_0^W = Rz(ψ) Ry(θ) Rx(φ) for ξ = (ψ, θ, φ).
Matrix3 rotation_from_zyx(const Vector3& xi);
/// ξ = (ψ, θ, φ) of a rotation, θ ∈ [−π/2, π/2].
Vector3 zyx_from_rotation(const Matrix3& W_R_0);

/// Eq. 41: G(ξ) with ω_W = G ξ̇ (ω in world coordinates).
Matrix3 euler_rate_matrix(const Vector3& xi);
/// Eq. 42: ξ̇ = G⁻¹ ω_W. Singular at θ = ±π/2 (cos θ = 0), where it returns non-finite values.
Vector3 euler_rates(const Vector3& xi, const Vector3& omega_W);

/// q̇ = ½ q ⊗ (0, ω_B) for a quaternion (w, x, y, z) and body-frame angular velocity.
Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q_wxyz, const Vector3& omega_B);
Matrix3 rotation_from_quaternion(const Eigen::Vector4d& q_wxyz);
Eigen::Vector4d quaternion_from_rotation(const Matrix3& W_R_0);

}  // namespace rbdc::sim
