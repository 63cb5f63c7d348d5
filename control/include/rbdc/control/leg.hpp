// A quadruped leg as the trot controllers see it: ab/ad, hip and knee joints, the hip and knee
// moving the foot in the leg's sagittal plane; its geometry read from the model and the planar
// inverse kinematics of the hip-knee pair.
#pragma once

#include <vector>

#include "rbdc/model.hpp"

namespace rbdc::control {

/// One leg's planar geometry, read from the model at q = 0 (hip and knee axes along ±y of the
/// trunk, leg hanging straight down).
struct LegGeometry {
  int abad_q = 0, hip_q = 0, knee_q = 0;  ///< indices into q
  int abad_v = 0, hip_v = 0, knee_v = 0;  ///< indices into v
  double hip_sign = 1, knee_sign = 1;     ///< +1 when positive rotation swings the foot forward
  double thigh = 0, shank = 0;            ///< m, sagittal link lengths
  Vector3 hip_in_trunk = Vector3::Zero(); ///< hip joint origin, trunk coordinates
};

/// Reads every foot's leg (foot body = knee, its parent = hip, its parent = ab/ad on the trunk).
/// Throws std::invalid_argument naming the foot when a leg does not have that shape.
std::vector<LegGeometry> leg_geometry(const Model& model);

/// Planar two-link inverse kinematics: hip and knee angles placing the foot at (x, z) relative to
/// the hip joint (trunk x forward, z up), knee bent backwards. Unreachable targets are clamped.
Eigen::Vector2d leg_inverse_kinematics(const LegGeometry& leg, double x, double z);

}  // namespace rbdc::control
