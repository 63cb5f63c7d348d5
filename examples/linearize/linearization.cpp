#include "linearization.hpp"

#include <cmath>

#include "rbdc/rbdc.hpp"

namespace linearize {

namespace {

Eigen::Quaterniond orientation(const Config& q) {
  return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
}

rbdc::Matrix3 skew(const rbdc::Vector3& w) { return rbdc::skew(w); }

/// J_r⁻¹(θ) of SO(3): θ̇ = J_r⁻¹(θ) ω when R = R̄ exp(θ̃) and Ṙ = R ω̃.
rbdc::Matrix3 inverse_right_jacobian(const rbdc::Vector3& theta) {
  const double angle = theta.norm();
  const rbdc::Matrix3 T = skew(theta);
  // 1/θ² − (1 + cos θ)/(2θ sin θ), → 1/12 as θ → 0
  const double k = angle < 1e-4 ? 1.0 / 12.0
                                 : 1.0 / (angle * angle) -
                                       (1.0 + std::cos(angle)) / (2.0 * angle * std::sin(angle));
  return rbdc::Matrix3::Identity() + 0.5 * T + k * T * T;
}

/// The chart's inverse: δ with q = q̄ ⊕ δ (δθ = log(R̄ᵀR), δp = R̄ᵀ(p − p̄), joints q − q̄).
Tangent chart_inverse(const Config& q_bar, const Config& q) {
  Tangent delta;
  const Eigen::Quaterniond R_bar = orientation(q_bar);
  const Eigen::AngleAxisd relative(R_bar.conjugate() * orientation(q));
  delta.head<3>() = relative.angle() * relative.axis();
  delta.segment<3>(3) = R_bar.conjugate() * (q.head<3>() - q_bar.head<3>());
  delta.tail<nu>() = q.tail<nu>() - q_bar.tail<nu>();
  return delta;
}

Tangent generated_forward_dynamics(const Config& q, const Tangent& v, const Torques& tau,
                                   const Forces& f) {
  Tangent a;
  gen::forward_dynamics(q, v, tau, f, a);
  return a;
}

}  // namespace

OperatingPoint standing_equilibrium(const rbdc::Model& model) {
  OperatingPoint op;
  op.q << 0, 0, 0.3, 1, 0, 0, 0, 0, -0.8, 1.6, 0, -0.8, 1.6, 0, -0.8, 1.6, 0, -0.8, 1.6;
  op.v.setZero();
  rbdc::Data data(model);
  const rbdc::VectorX g = rbdc::gravity_terms(model, data, op.q);
  const rbdc::MatrixX J = rbdc::feet_jacobian(model, data, op.q);
  // Minimum-norm foot forces carrying the trunk rows of g: J_tᵀ f = g_t, f = J_t (J_tᵀ J_t)⁻¹ g_t.
  const Eigen::Matrix<double, 3 * gen::n_feet, 6> J_t = J.leftCols<6>();
  const Eigen::Matrix<double, 3 * gen::n_feet, 1> f = J_t * (J_t.transpose() * J_t).ldlt().solve(g.head<6>());
  op.f = Eigen::Map<const Forces>(f.data());
  // τ holds the joints: Sᵀτ = g − Jᵀf on the joint rows, so M a = Sᵀτ + Jᵀf − g = 0.
  op.tau = g.tail<nu>() - (J.transpose() * f).tail<nu>();
  return op;
}

Linearization continuous(const OperatingPoint& op) {
  gen::MassMatrix<double> da_dq, da_dv;
  Eigen::Matrix<double, nv, nu> da_dtau;
  Eigen::Matrix<double, nv, 3 * gen::n_feet> da_df;
  gen::forward_dynamics_derivatives(op.q, op.v, op.tau, op.f, da_dq, da_dv, da_dtau, da_df);
  Linearization lin;
  lin.A << Eigen::Matrix<double, nv, nv>::Zero(), Eigen::Matrix<double, nv, nv>::Identity(), da_dq, da_dv;
  lin.B << Eigen::Matrix<double, nv, nu>::Zero(), da_dtau;
  return lin;
}

Linearization discrete(const Linearization& c, double dt) {
  const auto I = Eigen::Matrix<double, nv, nv>::Identity();
  const Eigen::Matrix<double, nv, nv> da_dq = c.A.bottomLeftCorner<nv, nv>();
  const Eigen::Matrix<double, nv, nv> da_dv = c.A.bottomRightCorner<nv, nv>();
  const Eigen::Matrix<double, nv, nu> da_dtau = c.B.bottomRows<nv>();
  // ∂v⁺/∂(δq, v, τ) = (dt ∂a/∂q, 1 + dt ∂a/∂v, dt ∂a/∂τ); δq⁺ = δq + dt v⁺ to first order.
  const Eigen::Matrix<double, nv, nv> dvp_dq = dt * da_dq;
  const Eigen::Matrix<double, nv, nv> dvp_dv = I + dt * da_dv;
  Linearization d;
  d.A << I + dt * dvp_dq, dt * dvp_dv, dvp_dq, dvp_dv;
  d.B << dt * dt * da_dtau, dt * da_dtau;
  return d;
}

State continuous_dynamics(const rbdc::Model& model, const OperatingPoint& op, const State& x,
                          const Torques& tau) {
  const Tangent delta = x.head<nv>();
  const Tangent v = x.tail<nv>();
  Config q;
  rbdc::integrate(model, op.q, delta, q);
  State x_dot;
  // δθ̇ = J_r⁻¹(δθ) ω;  δṗ = R̄ᵀ ṗ = exp(δθ̃) v_B;  joints: q̇_j = v_j
  const rbdc::Vector3 theta = delta.head<3>();
  x_dot.head<3>() = inverse_right_jacobian(theta) * v.head<3>();
  x_dot.segment<3>(3) = orientation(op.q).conjugate() * orientation(q) * v.segment<3>(3);
  x_dot.segment<nu>(6) = v.tail<nu>();
  x_dot.tail<nv>() = generated_forward_dynamics(q, v, tau, op.f);
  return x_dot;
}

State discrete_step(const rbdc::Model& model, const OperatingPoint& op, const State& x,
                    const Torques& tau, double dt) {
  Config q, q_next;
  rbdc::integrate(model, op.q, Tangent(x.head<nv>()), q);
  const Tangent v_next = x.tail<nv>() + dt * generated_forward_dynamics(q, x.tail<nv>(), tau, op.f);
  rbdc::integrate(model, q, Tangent(dt * v_next), q_next);
  State x_next;
  x_next << chart_inverse(op.q, q_next), v_next;
  return x_next;
}

}  // namespace linearize
