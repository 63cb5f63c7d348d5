// Contact dynamics and impulse dynamics by the Schur complement of their KKT systems
// (contact_dynamics.hpp; docs/runtime.md, "Contact dynamics").
#include "rbdc/contact_dynamics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "argument_checks.hpp"
#include "contact_solve.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

ContactDynamicsData::ContactDynamicsData(const Model& model, std::vector<int> feet,
                                         BaumgarteGains baumgarte)
    : contact_feet(std::move(feet)), gains(baumgarte) {
  const int n_feet = static_cast<int>(model.feet.size());
  for (int foot : contact_feet) {
    if (foot < 0 || foot >= n_feet) {
      throw std::invalid_argument("rbdc::ContactDynamicsData: contact foot index " +
                                  std::to_string(foot) + " is not a foot of '" + model.name +
                                  "' (it has " + std::to_string(n_feet) + ")");
    }
  }
  const Eigen::Index nv = model.nv, nj = model.num_joints();
  const Eigen::Index m = 3 * static_cast<Eigen::Index>(contact_feet.size());
  a = VectorX::Zero(nv);
  lambda = VectorX::Zero(m);
  v_plus = VectorX::Zero(nv);
  impulse = VectorX::Zero(m);
  da_dq = MatrixX::Zero(nv, nv);
  da_dv = MatrixX::Zero(nv, nv);
  da_dtau = MatrixX::Zero(nv, nj);
  dlambda_dq = MatrixX::Zero(m, nv);
  dlambda_dv = MatrixX::Zero(m, nv);
  dlambda_dtau = MatrixX::Zero(m, nj);
  J = MatrixX::Zero(m, nv);
  gamma = VectorX::Zero(m);
  Minv_Jt = MatrixX::Zero(nv, m);
  A = MatrixX::Zero(m, m);
  A_llt = Eigen::LLT<MatrixX>(m);
  rhs = VectorX::Zero(m);
  step = VectorX::Zero(m);
  f_feet = Matrix3X::Zero(3, n_feet);
  r_joint = MatrixX::Zero(nv, nv);
  r_contact = MatrixX::Zero(m, nv);
  r_tau = MatrixX::Zero(nv, nj);
  dpddot_dq = MatrixX::Zero(m, nv);
  dpddot_dv = MatrixX::Zero(m, nv);
  dpdot_dq = MatrixX::Zero(m, nv);
  dp_dq = MatrixX::Zero(m, nv);
}

namespace detail {

void check_contact_data(const char* function, const Model& model, const ContactDynamicsData& contact) {
  if (contact.a.size() != model.nv || contact.f_feet.cols() != static_cast<Eigen::Index>(model.feet.size())) {
    throw std::invalid_argument(std::string("rbdc::") + function +
                                ": contact data was built for a different model than '" +
                                model.name + "'");
  }
}

void contact_delassus(const Model& model, Data& data, ContactDynamicsData& contact, const VectorRef& q) {
  feet_jacobian(model, data, q);
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    contact.J.middleRows<3>(3 * static_cast<Eigen::Index>(k)) =
        data.J.middleRows<3>(3 * static_cast<Eigen::Index>(contact.contact_feet[k]));
  }
  // M⁻¹Jᵀ by the factor of M; A = J M⁻¹Jᵀ (symmetric positive semi-definite)
  contact.Minv_Jt = contact.J.transpose();
  solve_with_mass_matrix(data, contact.Minv_Jt);
  contact.A.noalias() = contact.J * contact.Minv_Jt;
  const Eigen::Index m = contact.A.rows();
  if (m == 0) return;
  // A + μ1 with μ = ρ tr(A)/m + μ_floor: positive definite even when J is rank deficient
  contact.mu = kContactDampingRelative * contact.A.trace() / static_cast<double>(m) +
               kContactDampingFloor;
  contact.A.diagonal().array() += contact.mu;
  contact.A_llt.compute(contact.A);
  contact.A.diagonal().array() -= contact.mu;
}

void solve_delassus(ContactDynamicsData& contact, Eigen::Ref<VectorX> x) {
  // proximal point steps on ½λᵀAλ − bᵀλ: x ← x + (A + μ1)⁻¹(b − A x), x₀ = 0
  x.setZero();
  if (x.size() == 0) return;  // no contacts: nothing was factorised
  for (int s = 0; s < kContactProximalSteps; ++s) {
    contact.step = contact.rhs;
    contact.step.noalias() -= contact.A * x;
    contact.A_llt.solveInPlace(contact.step);
    x += contact.step;
  }
}

namespace {

void fill_nan(ContactDynamicsData& contact) {
  contact.a.setConstant(std::numeric_limits<double>::quiet_NaN());
  contact.lambda.setConstant(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

const VectorX& solve_contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                      const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                      const Matrix3X* anchors) {
  // a₀ = M⁻¹(Sᵀτ − c − g): forward dynamics without foot forces, leaving the factor of M
  contact.f_feet.setZero();
  forward_dynamics(model, data, q, v, tau, contact.f_feet);
  if (data.M_llt.info() != Eigen::Success) {
    fill_nan(contact);
    return contact.a;
  }
  contact.a = data.a;
  contact_delassus(model, data, contact, q);
  // γ = J̇v + kd J v + kp (p − p*): the contact points' classical acceleration at a = 0 and the
  // Baumgarte terms (J v is the feet velocity, Eq. 37)
  feet_bias_accelerations(model, data, q, v);
  if (contact.gains.kd != 0) feet_velocities(model, data, q, v);
  if (anchors != nullptr) feet_positions(model, data, q);
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    const Eigen::Index foot = contact.contact_feet[k];
    auto gamma_k = contact.gamma.segment<3>(3 * static_cast<Eigen::Index>(k));
    gamma_k = data.feet_bias_acceleration.col(foot);
    if (contact.gains.kd != 0) gamma_k += contact.gains.kd * data.feet_velocity.col(foot);
    if (anchors != nullptr) {
      gamma_k += contact.gains.kp *
                 (data.feet_position.col(foot) - anchors->col(static_cast<Eigen::Index>(k)));
    }
  }
  // (J M⁻¹Jᵀ) λ = −(J a₀ + γ);  a = a₀ + M⁻¹Jᵀλ
  contact.rhs = -contact.gamma;
  contact.rhs.noalias() -= contact.J * contact.a;
  solve_delassus(contact, contact.lambda);
  contact.a.noalias() += contact.Minv_Jt * contact.lambda;
  return contact.a;
}

void check_contact_call(const char* function, const Model& model, const Data& data,
                        const ContactDynamicsData& contact, const VectorRef& q, const VectorRef& v,
                        const VectorRef& tau) {
  check_qv(function, model, data, q, v);
  check_invertible_mass(function, model);
  check_contact_data(function, model, contact);
  check_size(function, "tau", tau.size(), model.num_joints());
}

const Matrix3X* checked_anchors(const char* function, const ContactDynamicsData& contact,
                                const Matrix3X* anchors) {
  if (anchors == nullptr) {
    if (contact.gains.kp != 0) {
      throw std::invalid_argument(std::string("rbdc::") + function +
                                  ": the Baumgarte gain kp is not zero: pass the contact anchors");
    }
    return nullptr;
  }
  check_size(function, "anchors (columns)", anchors->cols(),
             static_cast<Eigen::Index>(contact.contact_feet.size()));
  return contact.gains.kp != 0 ? anchors : nullptr;
}

}  // namespace detail

const VectorX& contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v, const VectorRef& tau) {
  detail::check_contact_call("contact_dynamics", model, data, contact, q, v, tau);
  detail::checked_anchors("contact_dynamics", contact, nullptr);
  return detail::solve_contact_dynamics(model, data, contact, q, v, tau, nullptr);
}

const VectorX& contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                const Matrix3X& anchors) {
  detail::check_contact_call("contact_dynamics", model, data, contact, q, v, tau);
  return detail::solve_contact_dynamics(model, data, contact, q, v, tau,
                                detail::checked_anchors("contact_dynamics", contact, &anchors));
}

const VectorX& impulse_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v_minus, double restitution) {
  detail::check_qv("impulse_dynamics", model, data, q, v_minus);
  detail::check_contact_data("impulse_dynamics", model, contact);
  if (!(restitution >= 0 && restitution <= 1)) {
    throw std::invalid_argument("rbdc::impulse_dynamics: restitution " +
                                std::to_string(restitution) + " is not in [0, 1]");
  }
  mass_matrix(model, data, q);
  data.M_llt.compute(data.M);
  if (data.M_llt.info() != Eigen::Success) {
    contact.v_plus.setConstant(std::numeric_limits<double>::quiet_NaN());
    contact.impulse.setConstant(std::numeric_limits<double>::quiet_NaN());
    return contact.v_plus;
  }
  detail::contact_delassus(model, data, contact, q);
  // (J M⁻¹Jᵀ) Λ = −(1 + e) J v⁻;  v⁺ = v⁻ + M⁻¹JᵀΛ
  contact.gamma.noalias() = (1 + restitution) * (contact.J * v_minus);
  contact.rhs = -contact.gamma;
  detail::solve_delassus(contact, contact.impulse);
  contact.v_plus = v_minus;
  contact.v_plus.noalias() += contact.Minv_Jt * contact.impulse;
  return contact.v_plus;
}

}  // namespace rbdc
