#include "rbdc/control/pd_trot.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "rbdc/sim/smoothstep.hpp"

namespace rbdc::control {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// A point of the cubic Bézier curve with control points P0..P3 at s ∈ [0, 1].
Eigen::Vector2d bezier(const std::array<Eigen::Vector2d, 4>& P, double s) {
  const double r = 1 - s;
  return r * r * r * P[0] + 3 * r * r * s * P[1] + 3 * r * s * s * P[2] + s * s * s * P[3];
}

}  // namespace

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
  const double ramp = sim::smoothstep(0, gait_.ramp_time, t_);
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

PdTrotController::PdTrotController(const Model& model, const GaitParameters& gait,
                                   const PdGains& gains, double foot_radius)
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

void PdTrotController::desired_angles() {
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

std::vector<sim::Parameter> PdTrotController::parameters() const {
  return {{"period", gait_.period},
          {"duty_factor", gait_.duty_factor},
          {"step_length", gait_.step_length},
          {"step_height", gait_.step_height},
          {"stance_height", gait_.stance_height},
          {"ramp_time", gait_.ramp_time},
          {"coupling", gait_.coupling},
          {"kp", gains_.kp},
          {"kd", gains_.kd}};
}

const VectorX& PdTrotController::update(const sim::ControllerInput& input) {
  generator_.advance(input.dt);
  desired_angles();
  // Eq. 44 (restoring sign): τ = k_p (q_d − q) − k_d q̇.
  tau_ = gains_.kp * (q_desired_ - input.q.tail(q_desired_.size())) -
         gains_.kd * input.v.tail(tau_.size());
  return tau_;
}

VectorX PdTrotController::initial_configuration() const {
  VectorX q = VectorX::Zero(model_.nq);
  q[3] = 1;  // identity quaternion
  q.tail(q_desired_.size()) = q_desired_;
  // Trunk height: foot centres one radius above the ground under the hips.
  q[2] = gait_.stance_height - legs_.front().hip_in_trunk.z() + foot_radius_;
  return q;
}

}  // namespace rbdc::control
