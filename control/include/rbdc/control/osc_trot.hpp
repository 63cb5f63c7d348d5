// The trot controller of paper 001 Section 5 (Fig. 6) for the Mini Cheetah: a fixed trot schedule
// alternates the diagonal stance pairs LF+RH and RF+LH; swing legs follow a swing curve to a
// Raibert touch-down point with a PD servo on the foot position; stance legs get a passive
// virtual-leg torque τ_st,p and, once both stance feet are down, a trunk attitude law:
//   - OperationalSpace: Eqs. 49-55 with the generated closed-chain recursion (no force sensing);
//   - OperationalSpaceOpenChain: Eq. 50 as the paper prints it: Λ_t and b_t from the generated
//     open-chain recursion with the measured contact forces, J̃_tᵀ from the closed chain (with the
//     open-chain J̄_tᵀ instead, the loop τ → measured F → τ diverges on the Mini Cheetah:
//     docs/osc_control.md);
//   - HipTorque: Eqs. 56-57, roll and pitch PD torques added at the ab/ad and hip joints.
// The Mini Cheetah has no knee springs, so τ_st,p is a virtual leg spring between hip and foot
// (with a gravity feed-forward) playing the role of the paper's passive knee spring and thrust.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rbdc/control/attitude.hpp"
#include "rbdc/control/leg.hpp"
#include "rbdc/control/mini_cheetah.hpp"
#include "rbdc/control/operational_space_law.hpp"
#include "rbdc/model.hpp"
#include "rbdc/sim/controller.hpp"

namespace rbdc::control {

enum class StanceControl { OperationalSpace, OperationalSpaceOpenChain, HipTorque };
const char* to_string(StanceControl control);  ///< "osc", "osc-open", "raibert"
/// Parses "osc", "osc-open" or "raibert"; throws std::invalid_argument naming the value.
StanceControl parse_stance_control(const std::string& name);

struct TrotParameters {
  double speed = 1.0;            ///< m/s, desired forward speed after the ramp
  double speed_ramp = 1.5;       ///< s, desired speed grows linearly 0 → speed
  double step_duration = 0.15;   ///< s, one stance (= one swing) of a diagonal pair
  double leg_length = 0.25;      ///< m, rest length of the virtual leg (hip joint to foot point)
  double leg_stiffness = 2000;   ///< N/m, virtual leg spring
  double leg_damping = 60;       ///< N·s/m
  double swing_height = 0.06;    ///< m, apex of the swing curve above the ground
  double velocity_gain = 0.04;   ///< s, Raibert correction k_v
  double velocity_integral_gain = 0.3;  ///< Raibert correction on ∫(v_d − v) dt, 1/1
  double force_filter_time = 2e-2;  ///< s, first-order low-pass of the measured forces (osc-open)
  double yaw_gain = 0.03;        ///< m·s/rad, leg scissoring per yaw rate (paper 001 Sec. 5)
  double swing_kp = 800;         ///< N/m, foot-position servo
  double swing_kd = 20;          ///< N·s/m
  double contact_tolerance = 2e-3;  ///< m, a foot this close to the ground counts as down
  double ground_mass = 0;        ///< kg, big-ground inertia (0: Eq. 58 default)
  Vector6 weights = default_task_weights();                // Eq. 54
  AttitudeGains osc_gains{900, 60, 900, 60};              // Eqs. 51-52, 1/s² and 1/s
  AttitudeGains hip_gains{6, 0.3, 6, 0.3};                // Eqs. 56-57, N·m/rad, N·m·s/rad
};

/// The scalar parameters by name (rbdc-osc-trot --set, Controller::parameters()): each pointer
/// into `p`; osc_kp, osc_kd, hip_kp and hip_kd point at the roll gain, and set_parameter copies it
/// to pitch.
std::vector<std::pair<const char*, double*>> named_parameters(TrotParameters& p);
/// Sets one named parameter; throws std::invalid_argument for an unknown name.
void set_parameter(TrotParameters& p, const std::string& name, double value);

/// What the controller did in its last update (for logging and the tests).
struct ControllerStatus {
  StancePair pair = StancePair::LfRh;
  bool attitude_control = false;  ///< both stance feet down: the stance law is running
  TrunkAttitude attitude;
  SetPoint roll_desired, pitch_desired;
  StanceTorques stance;           ///< Eq. 53/55 details (OSC controllers)
};

class OscTrotController final : public sim::Controller {
 public:
  /// `model` is the Mini Cheetah the generated code was made from (hip placements, joint axes,
  /// total mass); foot_radius is the contact sphere radius (feet rest one radius above ground).
  OscTrotController(const Model& model, const TrotParameters& parameters, StanceControl control,
                    double foot_radius);

  std::string name() const override { return to_string(control_); }
  std::vector<sim::Parameter> parameters() const override;
  /// Standing at rest on flat ground, trunk level, each foot leg_length below its hip joint.
  VectorX initial_configuration() const override;
  /// Only OperationalSpaceOpenChain reads the measured foot forces.
  bool uses_foot_forces() const override {
    return control_ == StanceControl::OperationalSpaceOpenChain;
  }
  /// Joint torques (12) for time input.t, state q (19), v (18).
  const VectorX& update(const sim::ControllerInput& input) override;
  const ControllerStatus& status() const { return status_; }
  StanceControl control() const { return control_; }

 private:
  struct Leg {
    Vector3 hip_in_trunk;   ///< hip joint origin, trunk coordinates
    double abad_axis_x = 1; ///< ab/ad axis · trunk x (±1)
    double hip_axis_y = 1;  ///< hip axis · trunk y (±1)
    LegGeometry geometry;   ///< planar hip-knee geometry (standing IK)
  };
  const JointTorques& torques(double t, const double* q, const double* v, const FeetForces& measured);
  void start_step(int step, const double* q);
  void swing_torques(double t, const Vector3& p, const Matrix3& W_R_B, const Vector3& v_W,
                     double yaw_rate);
  void passive_stance_torques(const Vector3& p, const Matrix3& W_R_B, const double* v);
  void attitude_law(double t, const double* q, const double* v);

  TrotParameters parameters_;
  StanceControl control_;
  double foot_radius_, total_mass_, ground_mass_;
  std::vector<Leg> legs_;
  // Per update (fixed size, no heap).
  Eigen::Matrix<double, 3, kFeet> feet_;
  Eigen::Matrix<double, 3 * kFeet, kNv> J_;
  Eigen::Matrix<double, 3, kFeet> feet_velocity_;
  JointTorques tau_, tau_swing_, tau_passive_;
  VectorX tau_out_ = VectorX::Zero(kJoints);  ///< tau_ as the interface returns it
  TrunkTaskDynamics dynamics_, closed_chain_;
  // Gait and filter state.
  FeetForces filtered_forces_ = FeetForces::Zero();
  Eigen::Vector2d velocity_error_integral_ = Eigen::Vector2d::Zero();
  double last_update_ = 0;
  int step_ = -1;
  double step_start_ = 0;
  std::array<Vector3, kFeet> liftoff_;
  CubicSetPoint roll_spline_, pitch_spline_;
  ControllerStatus status_;
};

}  // namespace rbdc::control
