// The simulator of paper 000 Section 6.1: state x = (x_0, q, v_0, q̇) (Eq. 39), its derivative
// (Eq. 43) with compliant foot contact (Section 5), and fixed-step explicit integration.
#pragma once

#include <chrono>
#include <vector>

#include "rbdc/data.hpp"
#include "rbdc/sim/contact.hpp"
#include "rbdc/sim/contact_solver.hpp"
#include "rbdc/sim/dynamics.hpp"

namespace rbdc::sim {

enum class Integrator { Heun, RK4, SemiImplicitEuler };
/// Trunk orientation in the state: a unit quaternion (default, no singularity) or ZYX Euler
/// angles ξ = (ψ, θ, φ) with the rate conversion of Eqs. 41-42 (singular at θ = ±90°).
enum class StateKind { Quaternion, Euler };

struct SimOptions {
  double dt = 1e-4;  ///< s (Table I)
  Integrator integrator = Integrator::Heun;
  StateKind state = StateKind::Quaternion;
  ContactParameters contact;
  GroundPlane ground;
  bool contact_enabled = true;
};

/// Wall time spent in each phase of a step (seconds), filled when profiling is on; the controller's
/// share is RunSummary::controller_seconds (run.hpp).
struct PhaseTimes {
  double dynamics = 0;     ///< forward dynamics, M and its factor, feet Jacobians
  double contact = 0;      ///< foot kinematics, contact forces, friction solve
  double integration = 0;  ///< everything else inside step()
  long steps = 0;
};

class Simulator {
 public:
  /// `dynamics` must outlive the simulator and have a floating base (nq = nv + 1).
  Simulator(DynamicsModel& dynamics, const SimOptions& options);

  /// Sets the state from a configuration q (nq) and velocity v (nv), docs/conventions.md layout.
  void reset(const VectorX& q, const VectorX& v, double t = 0);
  /// Advances by one time step with the joint torques τ (nv − 6) held constant over it.
  void step(const VectorX& tau);

  double time() const { return t_; }
  const VectorX& q() const { return q_; }  ///< current configuration (quaternion form)
  const VectorX& v() const { return v_; }
  /// Contact state of every foot at the current state (with the torques of the last step, which
  /// the implicit friction depends on).
  const std::vector<FootContact>& contacts();
  /// Foot positions at the current state (3 × n_feet, world).
  const Matrix3X& feet_positions();

  const SimOptions& options() const { return options_; }
  void set_profiling(bool on) { profiling_ = on; }
  bool profiling() const { return profiling_; }
  PhaseTimes& profile() { return profile_; }

 private:
  using Clock = std::chrono::steady_clock;
  int position_size() const;
  /// x → configuration q (Euler angles become a quaternion).
  void configuration(const VectorX& x, VectorX& q) const;
  /// Position rates from positions and velocities: Eq. 42 (Euler) or the quaternion kinematics.
  void position_rate(const VectorX& x, const Eigen::Ref<const VectorX>& vel,
                     Eigen::Ref<VectorX> rate) const;
  /// ẋ of Eq. 43 at state x with torques `tau`.
  void derivative(const VectorX& x, const VectorX& tau, VectorX& xdot);
  /// Contacts, feet and accelerations a_ at (q, v) under τ.
  void evaluate(const VectorX& q, const Eigen::Ref<const VectorX>& v, const VectorX& tau);
  void sync_outputs();
  double seconds_since(Clock::time_point start) const;

  DynamicsModel& dynamics_;
  SimOptions options_;
  int nq_, nv_, n_feet_;
  double t_ = 0;
  bool profiling_ = false;
  PhaseTimes profile_;

  VectorX x_, k1_, k2_, k3_, k4_, x_stage_;  // state and integrator stages
  VectorX q_, v_, q_stage_, a_, last_tau_;
  ContactSolver solver_;
  Matrix3X p_feet_, v_feet_, f_feet_;
  std::vector<FootContact> contacts_;
};

const char* to_string(Integrator integrator);
const char* to_string(StateKind state);

}  // namespace rbdc::sim
