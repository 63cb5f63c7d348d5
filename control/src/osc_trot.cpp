#include "rbdc/control/osc_trot.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "mini_cheetah/stance_osc.hpp"
#include "rbdc/control/footstep.hpp"
#include "rbdc/control/trunk_dynamics.hpp"

namespace rbdc::control {
namespace gen = rbdc_gen::mini_cheetah::stance_osc;

// A stance foot counts as loaded above this fraction of its share of the weight (osc-open).
constexpr double kLoadedFraction = 0.25;

const char* to_string(StanceControl control) {
  switch (control) {
    case StanceControl::OperationalSpace: return "osc";
    case StanceControl::OperationalSpaceOpenChain: return "osc-open";
    case StanceControl::HipTorque: return "raibert";
  }
  return "?";
}

std::vector<std::pair<const char*, double*>> named_parameters(TrotParameters& p) {
  return {{"step_duration", &p.step_duration},
          {"leg_length", &p.leg_length},
          {"leg_stiffness", &p.leg_stiffness},
          {"leg_damping", &p.leg_damping},
          {"swing_height", &p.swing_height},
          {"velocity_gain", &p.velocity_gain},
          {"force_filter_time", &p.force_filter_time},
          {"yaw_gain", &p.yaw_gain},
          {"velocity_integral_gain", &p.velocity_integral_gain},
          {"swing_kp", &p.swing_kp},
          {"swing_kd", &p.swing_kd},
          {"speed_ramp", &p.speed_ramp},
          {"ground_mass", &p.ground_mass},
          {"osc_kp", &p.osc_gains.roll_kp},
          {"osc_kd", &p.osc_gains.roll_kd},
          {"hip_kp", &p.hip_gains.roll_kp},
          {"hip_kd", &p.hip_gains.roll_kd}};
}

void set_parameter(TrotParameters& p, const std::string& name, double value) {
  for (const auto& [key, target] : named_parameters(p))
    if (name == key) {
      *target = value;
      // One gain pair for roll and pitch.
      p.osc_gains.pitch_kp = p.osc_gains.roll_kp, p.osc_gains.pitch_kd = p.osc_gains.roll_kd;
      p.hip_gains.pitch_kp = p.hip_gains.roll_kp, p.hip_gains.pitch_kd = p.hip_gains.roll_kd;
      return;
    }
  throw std::invalid_argument("unknown trot parameter '" + name + "'");
}

StanceControl parse_stance_control(const std::string& name) {
  for (StanceControl c : {StanceControl::OperationalSpace, StanceControl::OperationalSpaceOpenChain,
                          StanceControl::HipTorque})
    if (name == to_string(c)) return c;
  throw std::invalid_argument("unknown controller '" + name + "' (expected osc, osc-open or raibert)");
}

OscTrotController::OscTrotController(const Model& model, const TrotParameters& parameters,
                                     StanceControl control, double foot_radius)
    : parameters_(parameters), control_(control), foot_radius_(foot_radius), total_mass_(0) {
  if (model.nq != kNq || model.nv != kNv || static_cast<int>(model.feet.size()) != kFeet)
    throw std::invalid_argument("OscTrotController: model '" + model.name +
                                "' is not the Mini Cheetah the generated code was made from");
  if (!(parameters.step_duration > 0) || !(parameters.leg_length > 0))
    throw std::invalid_argument("OscTrotController: step duration and leg length must be positive");
  for (const Body& body : model.bodies) total_mass_ += body.mass;
  ground_mass_ = parameters.ground_mass > 0 ? parameters.ground_mass : mini_cheetah_ground_mass();
  for (const LegGeometry& geometry : leg_geometry(model)) {
    Leg leg;
    leg.geometry = geometry;
    leg.hip_in_trunk = geometry.hip_in_trunk;
    const int abad = geometry.abad_v - 5, hip = geometry.hip_v - 5;  // v index 6 + (j − 1)
    const Matrix3 R_abad = model.joints[abad].rotation.transpose();
    const Matrix3 R_hip = R_abad * model.joints[hip].rotation.transpose();
    leg.abad_axis_x = (R_abad * model.joints[abad].axis).x() > 0 ? 1.0 : -1.0;
    leg.hip_axis_y = (R_hip * model.joints[hip].axis).y() > 0 ? 1.0 : -1.0;
    legs_.push_back(leg);
  }
  tau_.setZero();
  tau_swing_.setZero();
  tau_passive_.setZero();
}

VectorX OscTrotController::initial_configuration() const {
  VectorX q = VectorX::Zero(kNq);
  q[3] = 1;  // identity quaternion
  for (const Leg& leg : legs_) {
    const Eigen::Vector2d angles =
        leg_inverse_kinematics(leg.geometry, 0, -parameters_.leg_length);
    q[leg.geometry.hip_q] = angles[0];
    q[leg.geometry.knee_q] = angles[1];
  }
  q[2] = parameters_.leg_length - legs_.front().hip_in_trunk.z() + foot_radius_;
  return q;
}

void OscTrotController::start_step(int step, const double* q) {
  step_ = step;
  step_start_ = step * parameters_.step_duration;
  status_.pair = step % 2 == 0 ? StancePair::LfRh : StancePair::RfLh;
  status_.attitude_control = false;
  // The legs that start swinging leave from where their feet are now.
  const Eigen::Map<const Eigen::Matrix<double, kNq, 1>> q_map(q);
  gen::feet_positions<double>(q_map, feet_);
  for (int k : swing_feet(status_.pair)) liftoff_[k] = feet_.col(k);
}

void OscTrotController::swing_torques(double t, const Vector3& p, const Matrix3& W_R_B,
                                   const Vector3& v_W, double yaw_rate) {
  const TrotParameters& P = parameters_;
  const double remaining = step_start_ + P.step_duration - t;
  const double ramp = std::min(1.0, t / P.speed_ramp);
  // Heading frame: the trunk yaw only, so touch-down points ignore roll and pitch.
  const double yaw = std::atan2(W_R_B(1, 0), W_R_B(0, 0));
  const Matrix3 W_R_H = Eigen::AngleAxisd(yaw, Vector3::UnitZ()).toRotationMatrix();
  const Vector3 v_desired = W_R_H * Vector3(ramp * P.speed, 0, 0);
  Vector3 v_horizontal = v_W;
  v_horizontal.z() = 0;
  velocity_error_integral_ += (t - last_update_) * (v_desired - v_horizontal).head<2>();
  for (int k : swing_feet(status_.pair)) {
    const Vector3 hip_at_touchdown = p + W_R_H * legs_[k].hip_in_trunk + remaining * v_horizontal;
    Vector3 touchdown = raibert_touchdown(hip_at_touchdown, v_horizontal, v_desired,
                                          P.step_duration, P.velocity_gain, foot_radius_);
    // Integral action removes the steady speed deficit of the proportional heuristic.
    touchdown.head<2>() -= P.velocity_integral_gain * velocity_error_integral_;
    // Scissoring (paper 001 Sec. 5): front feet land outward of the turn, hind feet inward, so the
    // stance legs' lateral forces brake the yaw rate.
    const double scissor = (legs_[k].hip_in_trunk.x() > 0 ? 1.0 : -1.0) * P.yaw_gain * yaw_rate;
    touchdown += W_R_H * Vector3(0, scissor, 0);
    const SwingPoint target = swing_point(liftoff_[k], touchdown, P.swing_height, P.step_duration,
                                          (t - step_start_) / P.step_duration);
    // PD servo on the foot position, mapped to the leg joints by the foot Jacobian's transpose.
    const Vector3 force = P.swing_kp * (target.position - feet_.col(k)) +
                          P.swing_kd * (target.velocity - feet_velocity_.col(k));
    tau_swing_.segment<3>(3 * k) = J_.block<3, 3>(3 * k, 6 + 3 * k).transpose() * force;
  }
}

void OscTrotController::passive_stance_torques(const Vector3& p, const Matrix3& W_R_B, const double* v) {
  const TrotParameters& P = parameters_;
  const Vector3 omega_B(v[0], v[1], v[2]), v_B(v[3], v[4], v[5]);
  for (int k : stance_feet(status_.pair)) {
    const Vector3& r = legs_[k].hip_in_trunk;
    const Vector3 hip = p + W_R_B * r, hip_velocity = W_R_B * (v_B + omega_B.cross(r));
    const Vector3 leg = hip - feet_.col(k);
    const double length = leg.norm();
    const Vector3 u = leg / length;  // foot → hip
    const double length_rate = u.dot(hip_velocity - feet_velocity_.col(k));
    // Virtual leg spring: holds half the weight at the rest length (two legs in stance).
    const double weight_share = 0.5 * total_mass_ * 9.81 / std::max(u.z(), 0.3);
    const double thrust = P.leg_stiffness * (P.leg_length - length) - P.leg_damping * length_rate +
                          weight_share;
    // The foot pushes the ground along −u; τ = J_legᵀ F for that foot force.
    tau_passive_.segment<3>(3 * k) = J_.block<3, 3>(3 * k, 6 + 3 * k).transpose() * (-thrust * u);
  }
}

void OscTrotController::attitude_law(double t, const double* q, const double* v) {
  status_.roll_desired = roll_spline_.at(t);
  status_.pitch_desired = pitch_spline_.at(t);
  const std::array<int, 2> feet = stance_feet(status_.pair);
  if (control_ == StanceControl::HipTorque) {
    // Eqs. 56-57: the PD output is a trunk moment; a joint torque τ about axis a pushes the trunk
    // with −τ a, so each stance leg applies τ = −(a · e) u on its ab/ad (e = x) and hip (e = y).
    const Eigen::Vector2d u = attitude_pd(parameters_.hip_gains, status_.attitude,
                                          status_.roll_desired, status_.pitch_desired);
    tau_ = tau_swing_ + tau_passive_;
    for (int k : feet) {
      tau_[3 * k] -= legs_[k].abad_axis_x * u[0];
      tau_[3 * k + 1] -= legs_[k].hip_axis_y * u[1];
    }
    return;
  }
  if (control_ == StanceControl::OperationalSpace) {
    closed_chain_dynamics(q, v, status_.pair, ground_mass_, dynamics_);
  } else {  // Eq. 50: open-chain Λ_t, b_t (measured forces), closed-chain J̃_tᵀ
    closed_chain_dynamics(q, v, status_.pair, ground_mass_, closed_chain_);
    open_chain_dynamics(q, v, filtered_forces_, dynamics_);
    dynamics_.JbarT = closed_chain_.JbarT;
  }
  const std::array<int, 6> stance_joints = {3 * feet[0], 3 * feet[0] + 1, 3 * feet[0] + 2,
                                            3 * feet[1], 3 * feet[1] + 1, 3 * feet[1] + 2};
  const Eigen::Vector2d attitude_acceleration = attitude_pd(
      parameters_.osc_gains, status_.attitude, status_.roll_desired, status_.pitch_desired);
  operational_space_stance_torques<6>(dynamics_, stance_joints, tau_swing_, tau_passive_,
                                   attitude_acceleration, parameters_.weights, status_.stance);
  tau_ = tau_swing_ + status_.stance.tau;
}

std::vector<sim::Parameter> OscTrotController::parameters() const {
  TrotParameters copy = parameters_;
  std::vector<sim::Parameter> list;
  for (const auto& [name, value] : named_parameters(copy)) list.push_back({name, *value});
  return list;
}

const VectorX& OscTrotController::update(const sim::ControllerInput& input) {
  FeetForces measured = FeetForces::Zero();
  if (uses_foot_forces()) {
    if (input.foot_forces.cols() != kFeet)
      throw std::invalid_argument("OscTrotController: " + name() + " needs the measured foot forces");
    measured = input.foot_forces;
  }
  tau_out_ = torques(input.t, input.q.data(), input.v.data(), measured);
  return tau_out_;
}

const JointTorques& OscTrotController::torques(double t, const double* q, const double* v,
                                               const FeetForces& measured) {
  const int step = static_cast<int>(std::floor(t / parameters_.step_duration));
  if (step != step_) start_step(step, q);
  const Eigen::Map<const Eigen::Matrix<double, kNq, 1>> q_map(q);
  const Eigen::Map<const Eigen::Matrix<double, kNv, 1>> v_map(v);
  gen::feet_positions<double>(q_map, feet_);
  gen::feet_jacobian<double>(q_map, J_);
  for (int k = 0; k < kFeet; ++k) feet_velocity_.col(k) = J_.middleRows<3>(3 * k) * v_map;
  const Vector3 p(q[0], q[1], q[2]);
  const Matrix3 W_R_B = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  status_.attitude = trunk_attitude(q, v);
  // The stiff simulated ground makes foot forces ring at the contact's own frequency; like a real
  // force sensor's filter, a first-order low-pass keeps that out of Eq. 50's b_t.
  const double alpha = std::min(1.0, (t - last_update_) / parameters_.force_filter_time);
  filtered_forces_ += alpha * (measured - filtered_forces_);

  tau_swing_.setZero();
  tau_passive_.setZero();
  swing_torques(t, p, W_R_B, W_R_B * Vector3(v[3], v[4], v[5]),
                (W_R_B * Vector3(v[0], v[1], v[2])).z());
  passive_stance_torques(p, W_R_B, v);

  // Attitude control starts once both stance feet are down (paper 001 Sec. 6.2: "after firm
  // footholds are achieved"); the splines then lead roll and pitch back to level by lift-off.
  if (!status_.attitude_control) {
    const std::array<int, 2> feet = stance_feet(status_.pair);
    const double down = foot_radius_ + parameters_.contact_tolerance;
    bool footholds = feet_(2, feet[0]) <= down && feet_(2, feet[1]) <= down;
    // The open chain also needs the feet loaded: its b_t takes the measured forces as given, and
    // unloaded feet would ask the legs to hold the trunk against a free fall.
    if (control_ == StanceControl::OperationalSpaceOpenChain)
      for (int k : feet) footholds = footholds && filtered_forces_(2, k) > kLoadedFraction * 0.5 * total_mass_ * 9.81;
    if (footholds) {
      status_.attitude_control = true;
      const double liftoff = step_start_ + parameters_.step_duration;
      roll_spline_ = CubicSetPoint(t, status_.attitude.roll, status_.attitude.roll_rate, liftoff, 0);
      pitch_spline_ = CubicSetPoint(t, status_.attitude.pitch, status_.attitude.pitch_rate, liftoff, 0);
    }
  }
  if (status_.attitude_control)
    attitude_law(t, q, v);
  else
    tau_ = tau_swing_ + tau_passive_;
  last_update_ = t;
  return tau_;
}

}  // namespace rbdc::control
