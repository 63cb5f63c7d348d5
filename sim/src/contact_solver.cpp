#include "rbdc/sim/contact_solver.hpp"

#include <chrono>
#include <cmath>

namespace rbdc::sim {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
}  // namespace

void ContactSolver::accelerations(DynamicsModel& dyn, const ContactParameters& p, const GroundPlane& ground,
                                  double dt, const VectorX& q, const Eigen::Ref<const VectorX>& v,
                                  const VectorX& tau, Matrix3X& p_feet, Matrix3X& v_feet,
                                  std::vector<FootContact>& contacts, Matrix3X& f_feet, VectorX& a) {
  const int n_feet = dyn.n_feet(), nv = dyn.nv();
  dyn.feet_state(q.data(), v.data(), p_feet.data(), v_feet.data());
  const Vector3 n = ground.normal();
  const Vector3 d = -p.foot_radius * n;  // C_k − p_fk (Eq. 33: r along the contact normal)
  if (p.at_contact_point) dyn.feet_angular_jacobian(q.data(), Jw_);
  active_.clear();
  f_feet.setZero(3, n_feet);
  for (int k = 0; k < n_feet; ++k) {
    Vector3 v_contact = v_feet.col(k);
    if (p.at_contact_point) v_contact += (Jw_.middleRows<3>(3 * k) * v).cross(d);  // v_Ck = v_fk + ω × d
    contacts[k] = foot_contact(p, ground, p_feet.col(k), v_contact);
    if (contacts[k].active) active_.push_back(k);
  }
  const bool legacy = !p.at_contact_point && p.friction_update == FrictionUpdate::Explicit;
  if (active_.empty() || legacy) {  // forces at the foot points: the generated forward dynamics
    for (int k : active_) f_feet.col(k) = contacts[k].force_W;
    const Clock::time_point start = timing ? Clock::now() : Clock::time_point{};
    dyn.forward_dynamics(q.data(), v.data(), tau.data(), f_feet.data(), a.data());
    if (timing) dynamics_seconds += since(start);
    return;
  }
  // Contact-point Jacobian rows in contact-frame coordinates: R_Cᵀ (J_fk − [d]× J_ω,k).
  Clock::time_point start = timing ? Clock::now() : Clock::time_point{};
  dyn.mass_matrix(q.data(), M_);
  llt_.compute(M_);
  dyn.feet_jacobian(q.data(), J_);
  if (timing) dynamics_seconds += since(start);
  const int m = static_cast<int>(active_.size());
  JC_.resize(3 * m, nv);
  for (int i = 0; i < m; ++i) {
    const int k = active_[static_cast<size_t>(i)];
    JC_.middleRows<3>(3 * i) = J_.middleRows<3>(3 * k);
    if (p.at_contact_point) JC_.middleRows<3>(3 * i) -= skew(d) * Jw_.middleRows<3>(3 * k);
    JC_.middleRows<3>(3 * i) = ground.W_R_C().transpose() * JC_.middleRows<3>(3 * i);
  }
  if (timing) start = Clock::now();
  X_ = JC_.transpose();
  llt_.solveInPlace(X_);  // M⁻¹ J_Cᵀ
  rhs_.resize(nv);
  dyn.bias_forces(q.data(), v.data(), rhs_.data());
  rhs_ = -rhs_;
  rhs_.tail(nv - 6) += tau;
  llt_.solveInPlace(rhs_);
  a = rhs_;  // a₀
  if (timing) dynamics_seconds += since(start);
  f_.resize(3 * m);
  for (int i = 0; i < m; ++i) f_.segment<3>(3 * i) = contacts[active_[static_cast<size_t>(i)]].force_C;
  if (p.friction_update == FrictionUpdate::Implicit) {
    Phi_.noalias() = JC_ * X_;
    u_base_.noalias() = JC_ * (v + dt * a);
    implicit_friction_sweeps(p, dt);
  }
  a.noalias() += X_ * f_;
  for (int i = 0; i < m; ++i) {
    FootContact& c = contacts[active_[static_cast<size_t>(i)]];
    c.force_C = f_.segment<3>(3 * i);
    c.force_W = ground.W_R_C() * c.force_C;
    f_feet.col(active_[static_cast<size_t>(i)]) = c.force_W;
  }
}

void ContactSolver::implicit_friction_sweeps(const ContactParameters& p, double dt) {
  const int m = static_cast<int>(active_.size());
  for (int i = 0; i < m; ++i) f_.segment<2>(3 * i).setZero();
  // Gauss-Seidel: each foot sees the others' latest friction through Φ's off-diagonal blocks.
  for (int sweep = 0; sweep < 12; ++sweep) {
    for (int i = 0; i < m; ++i) {
      const double f_n = f_[3 * i + 2];
      // Slip velocity one step ahead without this foot's friction.
      Eigen::Vector2d u_free = u_base_.segment<2>(3 * i) - dt * Phi_.block<2, 2>(3 * i, 3 * i) * f_.segment<2>(3 * i);
      for (int j = 0; j < 3 * m; ++j) u_free += dt * f_[j] * Phi_.block<2, 1>(3 * i, j);
      if (p.friction == FrictionModel::PerAxis) {
        for (int axis = 0; axis < 2; ++axis) {
          const int r = 3 * i + axis;
          f_[r] = implicit_friction(p, u_free[axis], dt * Phi_(r, r), f_n);
          if (axis == 0) u_free[1] += dt * Phi_(r + 1, r) * f_[r];  // x's friction moves y's slip
        }
      } else {
        const double slip = u_free.norm();
        const double compliance = 0.5 * dt * (Phi_(3 * i, 3 * i) + Phi_(3 * i + 1, 3 * i + 1));
        f_.segment<2>(3 * i) =
            slip > 0 ? Eigen::Vector2d(implicit_friction(p, slip, compliance, f_n) / slip * u_free)
                     : Eigen::Vector2d::Zero();
      }
    }
  }
}

}  // namespace rbdc::sim
