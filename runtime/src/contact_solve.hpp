// The pieces contact_dynamics, impulse_dynamics and their derivatives share: the entry checks, the
// contact Jacobian rows, the Delassus matrix A = J M⁻¹ Jᵀ and its damped proximal solve
// (contact_dynamics.hpp documents μ and the number of steps).
#pragma once

#include "rbdc/contact_dynamics.hpp"

namespace rbdc::detail {

/// Throws std::invalid_argument if contact was built for another model than model.
void check_contact_data(const char* function, const Model& model, const ContactDynamicsData& contact);

/// contact.J ← the contact rows of the feet Jacobian; contact.Minv_Jt ← M⁻¹Jᵀ; contact.A ← J M⁻¹Jᵀ
/// and its damped factor. Needs data.M_llt factorised at q; leaves data.J at q.
void contact_delassus(const Model& model, Data& data, ContactDynamicsData& contact, const VectorRef& q);

/// x ← the solution of A x = contact.rhs by kContactProximalSteps proximal steps
///   x ← x + (A + μ1)⁻¹(rhs − A x) from x = 0 (uses contact.step).
void solve_delassus(ContactDynamicsData& contact, Eigen::Ref<VectorX> x);

/// Entry checks of contact_dynamics(_derivatives): sizes of q, v, tau; data and contact built for model.
void check_contact_call(const char* function, const Model& model, const Data& data,
                        const ContactDynamicsData& contact, const VectorRef& q, const VectorRef& v,
                        const VectorRef& tau);

/// The anchors the Baumgarte position term needs (null when kp = 0); throws if kp ≠ 0 and anchors
/// is null, or if anchors has not one column per contact.
const Matrix3X* checked_anchors(const char* function, const ContactDynamicsData& contact,
                                const Matrix3X* anchors);

/// The body of contact_dynamics after its checks; anchors null when kp = 0. Leaves data.M_llt,
/// contact.J, Minv_Jt, A and its factor at q.
const VectorX& solve_contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                      const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                      const Matrix3X* anchors);

}  // namespace rbdc::detail
