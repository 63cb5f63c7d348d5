#include "rbdc/sim/simulator.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "rbdc/sim/orientation.hpp"

namespace rbdc::sim {

// State layout x = [positions | v]:
//   quaternion: positions = q = (p_W, quaternion wxyz, joints)     (nq entries)
//   Euler:      positions = (p_W, ξ = (ψ, θ, φ), joints)           (nq − 1 entries)
// The velocity part is v = (ω_B, v_B, q̇) in both, so the dynamics are called unchanged.

Simulator::Simulator(DynamicsModel& dynamics, const SimOptions& options)
    : dynamics_(dynamics),
      options_(options),
      nq_(dynamics.nq()),
      nv_(dynamics.nv()),
      n_feet_(dynamics.n_feet()) {
  if (nq_ != nv_ + 1 || nv_ < 6)
    throw std::invalid_argument("Simulator: dynamics '" + dynamics.name() +
                                "' is not a floating-base robot (nq = " + std::to_string(nq_) +
                                ", nv = " + std::to_string(nv_) + ")");
  if (!(options.dt > 0)) throw std::invalid_argument("Simulator: the time step must be positive");
  const int nx = position_size() + nv_;
  for (VectorX* s : {&x_, &k1_, &k2_, &k3_, &k4_, &x_stage_}) s->setZero(nx);
  q_.setZero(nq_);
  q_[3] = 1;
  q_stage_ = q_;
  v_.setZero(nv_);
  a_.setZero(nv_);
  last_tau_.setZero(nv_ - 6);
  p_feet_.setZero(3, n_feet_);
  v_feet_.setZero(3, n_feet_);
  f_feet_.setZero(3, n_feet_);
  contacts_.resize(n_feet_);
}

int Simulator::position_size() const {
  return options_.state == StateKind::Quaternion ? nq_ : nq_ - 1;
}

void Simulator::reset(const VectorX& q, const VectorX& v, double t) {
  if (q.size() != nq_ || v.size() != nv_)
    throw std::invalid_argument("Simulator::reset: expected q of size " + std::to_string(nq_) +
                                " and v of size " + std::to_string(nv_));
  const int n_joints = nv_ - 6;
  x_.head<3>() = q.head<3>();
  const Eigen::Vector4d quaternion = q.segment<4>(3).normalized();
  if (options_.state == StateKind::Quaternion) {
    x_.segment<4>(3) = quaternion;
    x_.segment(7, n_joints) = q.tail(n_joints);
  } else {
    x_.segment<3>(3) = zyx_from_rotation(rotation_from_quaternion(quaternion));
    x_.segment(6, n_joints) = q.tail(n_joints);
  }
  x_.tail(nv_) = v;
  t_ = t;
  sync_outputs();
}

void Simulator::configuration(const VectorX& x, VectorX& q) const {
  const int n_joints = nv_ - 6;
  q.head<3>() = x.head<3>();
  if (options_.state == StateKind::Quaternion) {
    q.tail(nq_ - 3) = x.segment(3, nq_ - 3);
    q.segment<4>(3).normalize();  // Runge-Kutta stages leave the unit sphere slightly
  } else {
    q.segment<4>(3) = quaternion_from_rotation(rotation_from_zyx(x.segment<3>(3)));
    q.tail(n_joints) = x.segment(6, n_joints);
  }
}

void Simulator::position_rate(const VectorX& x, const Eigen::Ref<const VectorX>& vel,
                              Eigen::Ref<VectorX> rate) const {
  const int n_joints = nv_ - 6;
  const Vector3 omega_B = vel.head<3>();
  const Vector3 v_B = vel.segment<3>(3);
  if (options_.state == StateKind::Quaternion) {
    const Eigen::Vector4d quaternion = x.segment<4>(3);
    rate.head<3>() = rotation_from_quaternion(quaternion) * v_B;  // ṗ_W = R_0^W v_B
    rate.segment<4>(3) = quaternion_rate(quaternion, omega_B);
    rate.segment(7, n_joints) = vel.tail(n_joints);
  } else {
    // Eq. 42: ẋ_0 = T v_0 with v_0 = (ω, ṗ) in world coordinates, T = diag(G⁻¹, 1).
    const Vector3 xi = x.segment<3>(3);
    const Matrix3 W_R_0 = rotation_from_zyx(xi);
    rate.head<3>() = W_R_0 * v_B;
    rate.segment<3>(3) = euler_rates(xi, W_R_0 * omega_B);
    rate.segment(6, n_joints) = vel.tail(n_joints);
  }
}

double Simulator::seconds_since(Clock::time_point start) const {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void Simulator::evaluate(const VectorX& q, const Eigen::Ref<const VectorX>& v, const VectorX& tau) {
  const Clock::time_point start = profiling_ ? Clock::now() : Clock::time_point{};
  solver_.timing = profiling_;
  solver_.dynamics_seconds = 0;
  if (options_.contact_enabled) {
    solver_.accelerations(dynamics_, options_.contact, options_.ground, options_.dt, q, v, tau, p_feet_,
                          v_feet_, contacts_, f_feet_, a_);
  } else {
    dynamics_.feet_state(q.data(), v.data(), p_feet_.data(), v_feet_.data());
    for (FootContact& c : contacts_) c = FootContact{};
    f_feet_.setZero();
    dynamics_.forward_dynamics(q.data(), v.data(), tau.data(), f_feet_.data(), a_.data());
  }
  if (profiling_) {
    const double total = seconds_since(start);
    const double dynamics = options_.contact_enabled ? solver_.dynamics_seconds : total;
    profile_.dynamics += dynamics;
    profile_.contact += total - dynamics;
  }
}

void Simulator::derivative(const VectorX& x, const VectorX& tau, VectorX& xdot) {
  const int np = position_size();
  const auto vel = x.tail(nv_);
  configuration(x, q_stage_);
  // Section 5 contact forces and Eq. 43's last block rows: a = M⁻¹(Sᵀτ + J_Cᵀf − c − g).
  evaluate(q_stage_, vel, tau);
  position_rate(x, vel, xdot.head(np));
  // The state holds v_B = R_W^0 ṗ_W; a holds R_W^0 p̈_W, so v̇_B = R_W^0 p̈_W − ω_B × v_B.
  xdot.tail(nv_) = a_;
  xdot.segment<3>(np + 3) -= vel.head<3>().cross(vel.segment<3>(3));
}

void Simulator::step(const VectorX& tau) {
  if (tau.size() != nv_ - 6)
    throw std::invalid_argument("Simulator::step: expected " + std::to_string(nv_ - 6) +
                                " joint torques, got " + std::to_string(tau.size()));
  last_tau_ = tau;
  Clock::time_point start;
  const PhaseTimes before = profile_;
  if (profiling_) start = Clock::now();
  const double dt = options_.dt;
  switch (options_.integrator) {
    case Integrator::Heun:  // explicit trapezoid ("explicit 2nd-order Euler", Table I)
      derivative(x_, tau, k1_);
      x_stage_ = x_ + dt * k1_;
      derivative(x_stage_, tau, k2_);
      x_ += (0.5 * dt) * (k1_ + k2_);
      break;
    case Integrator::RK4:
      derivative(x_, tau, k1_);
      x_stage_ = x_ + (0.5 * dt) * k1_;
      derivative(x_stage_, tau, k2_);
      x_stage_ = x_ + (0.5 * dt) * k2_;
      derivative(x_stage_, tau, k3_);
      x_stage_ = x_ + dt * k3_;
      derivative(x_stage_, tau, k4_);
      x_ += (dt / 6) * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
      break;
    case Integrator::SemiImplicitEuler: {  // velocities first, positions with the new velocities
      const int np = position_size();
      derivative(x_, tau, k1_);
      x_.tail(nv_) += dt * k1_.tail(nv_);
      position_rate(x_, x_.tail(nv_), k1_.head(np));
      x_.head(np) += dt * k1_.head(np);
      break;
    }
  }
  if (options_.state == StateKind::Quaternion) x_.segment<4>(3).normalize();
  t_ += dt;
  sync_outputs();
  if (profiling_) {
    const double inside = (profile_.contact - before.contact) + (profile_.dynamics - before.dynamics);
    profile_.integration += seconds_since(start) - inside;
    ++profile_.steps;
  }
}

void Simulator::sync_outputs() {
  configuration(x_, q_);
  v_ = x_.tail(nv_);
}

const std::vector<FootContact>& Simulator::contacts() {
  const bool profiling = std::exchange(profiling_, false);  // outputs are not part of the step
  evaluate(q_, v_, last_tau_);
  profiling_ = profiling;
  return contacts_;
}

const Matrix3X& Simulator::feet_positions() {
  dynamics_.feet_state(q_.data(), v_.data(), p_feet_.data(), v_feet_.data());
  return p_feet_;
}

const char* to_string(Integrator integrator) {
  switch (integrator) {
    case Integrator::Heun: return "heun";
    case Integrator::RK4: return "rk4";
    case Integrator::SemiImplicitEuler: return "semi-implicit";
  }
  return "?";
}

const char* to_string(StateKind state) {
  return state == StateKind::Quaternion ? "quaternion" : "euler";
}

}  // namespace rbdc::sim
