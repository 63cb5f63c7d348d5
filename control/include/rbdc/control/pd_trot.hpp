// Trot reference of paper 000 Section 6.2: a central pattern generator (four coupled phase
// oscillators locked to trot offsets) drives per-leg foot trajectories, a straight stance line and
// a Bézier swing curve in the leg's sagittal plane; planar inverse kinematics turns them into hip
// and knee angles, with ab/ad held at 0. The PD law of Eq. 44 then tracks them.
#pragma once

#include <string>
#include <vector>

#include "rbdc/control/leg.hpp"
#include "rbdc/model.hpp"
#include "rbdc/sim/controller.hpp"

namespace rbdc::control {

struct GaitParameters {
  double period = 0.4;          ///< s, one full stride
  double duty_factor = 0.5;     ///< fraction of the period in stance (trot: 0.5)
  double step_length = 0.10;    ///< m, stance stroke along the trunk x axis
  double step_height = 0.06;    ///< m, swing apex above the stance line
  double stance_height = 0.25;  ///< m, foot point below the hip joint during stance
  double ramp_time = 0.5;       ///< s, step length and height grow 0 → full (smoothstep)
  double coupling = 5.0;        ///< 1/s, oscillator coupling gain
};

/// Trot foot-trajectory generator: oscillator phases → sagittal foot targets.
class TrotGenerator {
 public:
  /// Legs in model foot order; `trot_offsets` are the oscillators' phase offsets (rad), e.g.
  /// LF 0, RF π, LH π, RH 0.
  TrotGenerator(const GaitParameters& gait, std::vector<double> trot_offsets);
  /// Advances the oscillators by dt (explicit Euler on the coupled phase equations).
  void advance(double dt);
  /// Foot target of leg k relative to its nominal stance point (x forward, z up), at the current
  /// phase and ramp.
  Eigen::Vector2d foot_offset(int k) const;
  bool in_stance(int k) const;
  double phase(int k) const { return phase_[k]; }
  double time() const { return t_; }

 private:
  GaitParameters gait_;
  std::vector<double> offsets_, phase_, phase_rate_;
  double t_ = 0;
};

/// Eq. 44 as a restoring law: τ_i = k_p (q_d,i − q_i) − k_d q̇_i. (The paper prints
/// k_p(q_i − q_d,i) + k_d q̇_i, which pushes away from the target with positive gains.)
struct PdGains {
  double kp = 40.0;  ///< N·m/rad (Table I)
  double kd = 1.0;   ///< N·m·s/rad (Table I)
};

/// The complete trot controller of paper 000: generator + IK + PD, for a floating-base model.
class PdTrotController final : public sim::Controller {
 public:
  PdTrotController(const Model& model, const GaitParameters& gait, const PdGains& gains,
                   double foot_radius);
  std::string name() const override { return "pd-trot"; }
  std::vector<sim::Parameter> parameters() const override;
  /// A standing configuration on flat ground at the start of the gait (trunk level, feet on
  /// the ground at the nominal stance points).
  VectorX initial_configuration() const override;
  /// Advances the pattern generator by input.dt and returns the joint torques (nv − 6).
  const VectorX& update(const sim::ControllerInput& input) override;
  /// The desired joint angles of the last update (nv − 6).
  const VectorX& desired() const { return q_desired_; }
  const std::vector<LegGeometry>& legs() const { return legs_; }

 private:
  void desired_angles();
  Model model_;
  GaitParameters gait_;
  PdGains gains_;
  double foot_radius_;
  std::vector<LegGeometry> legs_;
  TrotGenerator generator_;
  VectorX q_desired_, tau_;
};

}  // namespace rbdc::control
