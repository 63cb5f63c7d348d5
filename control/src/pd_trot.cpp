#include "rbdc/sim/trot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rbdc/sim/smoothstep.hpp"

namespace rbdc::sim {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// A point of the cubic Bézier curve with control points P0..P3 at s ∈ [0, 1].
Eigen::Vector2d bezier(const std::array<Eigen::Vector2d, 4>& P, double s) {
  const double r = 1 - s;
  return r * r * r * P[0] + 3 * r * r * s * P[1] + 3 * r * s * s * P[2] + s * s * s * P[3];
}

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

TrotGenerator::TrotGenerator(const GaitParameters& gait, std::vector<double> trot_offsets)
    : gait_(gait), offsets_(std::move(trot_offsets)), phase_(offsets_), phase_rate_(offsets_.size()) {
  if (!(gait.period > 0) || !(gait.duty_factor > 0 && gait.duty_factor < 1))
    throw std::invalid_argument("TrotGenerator: the period must be positive and the duty factor in (0, 1)");
}

void TrotGenerator::advance(double dt) {
  // Coupled phase oscillators: θ̇_i = 2π/T + k Σ_j sin(θ_j − θ_i − (ψ_j − ψ_i)). Started on the
  // trot offsets they stay locked; the coupling pulls them back after any perturbation.
  const double omega = kTwoPi / gait_.period;
  const std::size_t n = phase_.size();
  for (std::size_t i = 0; i < n; ++i) {
    double rate = omega;
    for (std::size_t j = 0; j < n; ++j)
      rate += gait_.coupling * std::sin(phase_[j] - phase_[i] - (offsets_[j] - offsets_[i]));
    phase_rate_[i] = rate;
  }
  for (std::size_t i = 0; i < n; ++i) phase_[i] = std::fmod(phase_[i] + dt * phase_rate_[i], kTwoPi);
  t_ += dt;
}

bool TrotGenerator::in_stance(int k) const {
  const double s = std::fmod(phase_[k] + kTwoPi, kTwoPi) / kTwoPi;
  return s < gait_.duty_factor;
}

Eigen::Vector2d TrotGenerator::foot_offset(int k) const {
  const double ramp = smoothstep(0, gait_.ramp_time, t_);
  const double L = ramp * gait_.step_length, H = ramp * gait_.step_height;
  const double s = std::fmod(phase_[k] + kTwoPi, kTwoPi) / kTwoPi;
  if (s < gait_.duty_factor)  // stance: straight line from front to back on the ground
    return {L / 2 - L * s / gait_.duty_factor, 0};
  // Swing: cubic Bézier from back to front; the inner control points at 4H/3 give an apex of H.
  const std::array<Eigen::Vector2d, 4> P = {Eigen::Vector2d(-L / 2, 0), Eigen::Vector2d(-L / 2, 4 * H / 3),
                                            Eigen::Vector2d(L / 2, 4 * H / 3), Eigen::Vector2d(L / 2, 0)};
  return bezier(P, (s - gait_.duty_factor) / (1 - gait_.duty_factor));
}

namespace {

// Diagonal pairs in phase: front-left with hind-right, front-right with hind-left.
std::vector<double> trot_offsets(const std::vector<LegGeometry>& legs) {
  std::vector<double> offsets;
  for (const LegGeometry& leg : legs)
    offsets.push_back(leg.hip_in_trunk.x() * leg.hip_in_trunk.y() < 0 ? M_PI : 0.0);
  return offsets;
}

}  // namespace

TrotController::TrotController(const Model& model, const GaitParameters& gait, const PdGains& gains,
                               double foot_radius)
    : model_(model),
      gait_(gait),
      gains_(gains),
      foot_radius_(foot_radius),
      legs_(leg_geometry(model)),
      generator_(gait, trot_offsets(legs_)),
      q_desired_(VectorX::Zero(model.nv - 6)),
      tau_(VectorX::Zero(model.nv - 6)) {
  desired_angles();
}

void TrotController::desired_angles() {
  // Joint index j ≥ 1 sits at q[7 + j − 1]; desired angles are stored per joint (ab/ad stays 0).
  for (std::size_t k = 0; k < legs_.size(); ++k) {
    const LegGeometry& leg = legs_[k];
    const Eigen::Vector2d offset = generator_.foot_offset(static_cast<int>(k));
    const Eigen::Vector2d angles =
        leg_inverse_kinematics(leg, offset.x(), -gait_.stance_height + offset.y());
    q_desired_[leg.abad_q - 7] = 0;
    q_desired_[leg.hip_q - 7] = angles[0];
    q_desired_[leg.knee_q - 7] = angles[1];
  }
}

const VectorX& TrotController::update(double dt, const VectorX& q, const VectorX& v) {
  generator_.advance(dt);
  desired_angles();
  // Eq. 44 (restoring sign): τ = k_p (q_d − q) − k_d q̇.
  tau_ = gains_.kp * (q_desired_ - q.tail(q_desired_.size())) - gains_.kd * v.tail(tau_.size());
  return tau_;
}

VectorX TrotController::standing_configuration() const {
  VectorX q = VectorX::Zero(model_.nq);
  q[3] = 1;  // identity quaternion
  q.tail(q_desired_.size()) = q_desired_;
  // Trunk height: foot centres one radius above the ground under the hips.
  q[2] = gait_.stance_height - legs_.front().hip_in_trunk.z() + foot_radius_;
  return q;
}

}  // namespace rbdc::sim
