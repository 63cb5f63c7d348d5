#include "rbdc/control/leg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbdc::control {
namespace {

bool along_y(const Vector3& axis) { return std::abs(std::abs(axis.y()) - 1) < 1e-9; }

}  // namespace

std::vector<LegGeometry> leg_geometry(const Model& model) {
  std::vector<LegGeometry> legs;
  for (const Foot& foot : model.feet) {
    const int knee = foot.body;
    const int hip = knee > 0 ? model.parent[knee] : -1;
    const int abad = hip > 0 ? model.parent[hip] : -1;
    if (abad <= 0 || model.parent[abad] != 0)
      throw std::invalid_argument("leg_geometry: foot '" + foot.name +
                                  "' is not on the third body of a leg starting at the trunk");
    // Joint origins and axes in trunk coordinates at q = 0 (body axes are E_Tᵀ of each joint).
    const Joint& ja = model.joints[abad];
    const Joint& jh = model.joints[hip];
    const Joint& jk = model.joints[knee];
    const Matrix3 R_abad = ja.rotation.transpose();
    const Matrix3 R_hip = R_abad * jh.rotation.transpose();
    const Matrix3 R_knee = R_hip * jk.rotation.transpose();
    const Vector3 hip_origin = ja.translation + R_abad * jh.translation;
    const Vector3 knee_origin = hip_origin + R_hip * jk.translation;
    const Vector3 foot_point = knee_origin + R_knee * foot.offset;
    const Vector3 hip_axis = R_hip * jh.axis, knee_axis = R_knee * jk.axis;
    const Vector3 thigh = knee_origin - hip_origin, shank = foot_point - knee_origin;
    if (!along_y(hip_axis) || !along_y(knee_axis) || std::abs(thigh.x()) > 1e-9 ||
        std::abs(shank.x()) > 1e-9 || thigh.z() >= 0 || shank.z() >= 0)
      throw std::invalid_argument("leg_geometry: leg of foot '" + foot.name +
                                  "' is not a sagittal hip-knee leg hanging straight down at q = 0");
    LegGeometry leg;
    leg.abad_q = ja.q_index, leg.hip_q = jh.q_index, leg.knee_q = jk.q_index;
    leg.abad_v = ja.v_index, leg.hip_v = jh.v_index, leg.knee_v = jk.v_index;
    // A rotation about −y swings a hanging foot towards +x.
    leg.hip_sign = -hip_axis.y();
    leg.knee_sign = -knee_axis.y();
    leg.thigh = -thigh.z();
    leg.shank = -shank.z();
    leg.hip_in_trunk = hip_origin;
    legs.push_back(leg);
  }
  return legs;
}

Eigen::Vector2d leg_inverse_kinematics(const LegGeometry& leg, double x, double z) {
  // Foot: x = l1 sin α + l2 sin(α + β), z = −l1 cos α − l2 cos(α + β) (α hip, β knee, from down).
  const double l1 = leg.thigh, l2 = leg.shank;
  const double reach = std::clamp(std::hypot(x, z), std::abs(l1 - l2) + 1e-9, l1 + l2 - 1e-9);
  const double cos_knee = (reach * reach - l1 * l1 - l2 * l2) / (2 * l1 * l2);
  const double beta = std::acos(std::clamp(cos_knee, -1.0, 1.0));  // > 0: knee behind the foot
  const double alpha = std::atan2(x, -z) - std::atan2(l2 * std::sin(beta), l1 + l2 * std::cos(beta));
  return {leg.hip_sign * alpha, leg.knee_sign * beta};
}

}  // namespace rbdc::control
