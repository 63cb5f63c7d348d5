#include "rbdc/sim/contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rbdc::sim {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Gauss-Seidel stops when no tangential force moved by more than this fraction of the largest
// normal force in a sweep (or after the cap): 1e-8 is far below the friction's own resolution.
constexpr double kSweepTolerance = 1e-8;
constexpr int kMaxSweeps = 12;
}  // namespace

void ContactSolver::prepare(DynamicsModel& dyn) {
  const int nv = dyn.nv(), rows = 3 * dyn.n_feet();
  if (ltdl_ && ltdl_->size() == nv && JC_.rows() == rows) return;
  ltdl_.emplace(dyn.dof_parents());
  terms_.resize(nv, dyn.n_feet());
  JC_.setZero(rows, nv);
  JT_.setZero(2 * dyn.n_feet(), nv);
  Y_.setZero(nv, 2 * dyn.n_feet());
  DY_.setZero(nv, 2 * dyn.n_feet());
  Phi_.setZero(2 * dyn.n_feet(), 2 * dyn.n_feet());
  f_.setZero(2 * dyn.n_feet());
  u_base_.setZero(2 * dyn.n_feet());
  rhs_.setZero(nv);
  impulse_.setZero(nv);
  last_friction_.setZero(2, dyn.n_feet());
  active_.reserve(static_cast<size_t>(dyn.n_feet()));
}

void ContactSolver::accelerations(DynamicsModel& dyn, const ContactParameters& p, const GroundPlane& ground,
                                  double dt, const VectorX& q, const Eigen::Ref<const VectorX>& v,
                                  const VectorX& tau, Matrix3X& p_feet, Matrix3X& v_feet,
                                  std::vector<FootContact>& contacts, Matrix3X& f_feet, VectorX& a) {
  prepare(dyn);
  const int n_feet = dyn.n_feet(), nv = dyn.nv();
  const Clock::time_point start = timing ? Clock::now() : Clock::time_point{};
  dyn.step_terms(q.data(), v.data(), tau.data(), terms_, *ltdl_);
  if (timing) dynamics_seconds += since(start);
  p_feet = terms_.p_feet;
  v_feet = terms_.v_feet;
  const Vector3 n = ground.normal();
  const Vector3 d = -p.foot_radius * n;  // C_k − p_fk (Eq. 33: r along the contact normal)
  active_.clear();
  f_feet.setZero(3, n_feet);
  for (int k = 0; k < n_feet; ++k) {
    Vector3 v_contact = v_feet.col(k);
    if (p.at_contact_point) v_contact += terms_.omega_feet.col(k).cross(d);  // v_Ck = v_fk + ω × d
    contacts[k] = foot_contact(p, ground, p_feet.col(k), v_contact);
    if (contacts[k].active) active_.push_back(k);
    else last_friction_.col(k).setZero();
  }
  if (active_.empty()) {
    a = terms_.a_free;
    return;
  }
  // Contact-point Jacobian rows in contact-frame coordinates: R_Cᵀ (J_fk − [d]× J_ω,k).
  const int m = static_cast<int>(active_.size());
  const Matrix3 C_R_W = ground.W_R_C().transpose();
  for (int i = 0; i < m; ++i) {
    const int k = active_[static_cast<size_t>(i)];
    for (int c = 0; c < nv; ++c) {
      Vector3 column = terms_.J.block<3, 1>(3 * k, c);
      if (p.at_contact_point) column -= d.cross(terms_.Jw.block<3, 1>(3 * k, c));
      JC_.block<3, 1>(3 * i, c).noalias() = C_R_W * column;
    }
  }
  // The known forces (the explicit normal ones, and the explicit friction when asked for) go into
  // a₁ = a₀ + M⁻¹ J_Cᵀ f_known; only the implicit friction is left to solve for.
  const bool implicit = p.friction_update == FrictionUpdate::Implicit;
  rhs_.setZero();
  for (int i = 0; i < m; ++i) {
    Vector3 known = contacts[active_[static_cast<size_t>(i)]].force_C;
    if (implicit) known.head<2>().setZero();
    rhs_.noalias() += JC_.middleRows<3>(3 * i).transpose() * known;
  }
  ltdl_->solve_lt(rhs_);
  ltdl_->solve_dinv_l(rhs_);
  a = terms_.a_free + rhs_;
  if (implicit) {
    const int rows = 2 * m;  // tangential rows x, y of each foot in contact
    for (int i = 0; i < m; ++i) JT_.middleRows<2>(2 * i) = JC_.middleRows<2>(3 * i);
    const auto JT = JT_.topRows(rows);
    auto Y = Y_.leftCols(rows);
    Y = JT.transpose();
    ltdl_->solve_lt(Y);  // Y = L⁻ᵀ J_Tᵀ
    auto DY = DY_.leftCols(rows);
    DY = ltdl_->inverse_pivots().asDiagonal() * Y;
    for (int c = 0; c < rows; ++c)  // Φ = J_T M⁻¹ J_Tᵀ = Yᵀ D⁻¹ Y, symmetric
      for (int r = 0; r <= c; ++r) Phi_(r, c) = Phi_(c, r) = DY.col(r).dot(Y.col(c));
    rhs_ = v + dt * a;
    for (int r = 0; r < rows; ++r) u_base_[r] = JT.row(r).dot(rhs_);  // J_T (v + dt a₁)
    implicit_friction_sweeps(p, dt, contacts);
    impulse_.setZero();
    for (int r = 0; r < rows; ++r) impulse_ += f_[r] * Y.col(r);  // L⁻ᵀ J_Tᵀ f_t
    ltdl_->solve_dinv_l(impulse_);
    a += impulse_;  // a₁ + M⁻¹ J_Tᵀ f_t
    for (int i = 0; i < m; ++i) contacts[active_[static_cast<size_t>(i)]].force_C.head<2>() = f_.segment<2>(2 * i);
  }
  for (int k : active_) {
    FootContact& c = contacts[k];
    c.force_W = ground.W_R_C() * c.force_C;
    f_feet.col(k) = c.force_W;
  }
}

void ContactSolver::implicit_friction_sweeps(const ContactParameters& p, double dt,
                                             const std::vector<FootContact>& contacts) {
  const int m = static_cast<int>(active_.size()), rows = 2 * m;
  double largest_normal = 0;
  for (int i = 0; i < m; ++i) {
    f_.segment<2>(2 * i) = last_friction_.col(active_[static_cast<size_t>(i)]);  // warm start
    largest_normal = std::max(largest_normal, contacts[active_[static_cast<size_t>(i)]].force_C.z());
  }
  // Gauss-Seidel: each foot sees the others' latest friction through Φ's off-diagonal blocks.
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double change = 0;
    for (int i = 0; i < m; ++i) {
      const double f_n = contacts[active_[static_cast<size_t>(i)]].force_C.z();
      const Eigen::Vector2d previous = f_.segment<2>(2 * i);
      if (p.friction == FrictionModel::PerAxis) {
        // Each axis sees every other force's latest value, its own foot's other axis included:
        // leaving Φ_xy f_y out of the x equation stalled the sweeps short of the root, and a
        // four-foot stance crept at 0.07 mm/s.
        for (int r = 2 * i; r < 2 * i + 2; ++r) {
          double u_free = u_base_[r] - dt * Phi_(r, r) * f_[r];  // slip one step ahead without f_r
          for (int j = 0; j < rows; ++j) u_free += dt * Phi_(r, j) * f_[j];
          f_[r] = implicit_friction(p, u_free, dt * Phi_(r, r), f_n, f_[r]);
        }
      } else {
        // Slip velocity one step ahead without this foot's friction.
        Eigen::Vector2d u_free = u_base_.segment<2>(2 * i) - dt * Phi_.block<2, 2>(2 * i, 2 * i) * previous;
        for (int j = 0; j < rows; ++j) u_free += (dt * f_[j]) * Phi_.block<2, 1>(2 * i, j);
        const double slip = u_free.norm();
        const double compliance = 0.5 * dt * (Phi_(2 * i, 2 * i) + Phi_(2 * i + 1, 2 * i + 1));
        f_.segment<2>(2 * i) =
            slip > 0 ? Eigen::Vector2d(implicit_friction(p, slip, compliance, f_n, previous.dot(u_free) / slip) / slip * u_free)
                     : Eigen::Vector2d::Zero();
      }
      change = std::max(change, (f_.segment<2>(2 * i) - previous).cwiseAbs().maxCoeff());
    }
    if (change <= kSweepTolerance * largest_normal) break;
  }
  for (int i = 0; i < m; ++i) last_friction_.col(active_[static_cast<size_t>(i)]) = f_.segment<2>(2 * i);
}

}  // namespace rbdc::sim
