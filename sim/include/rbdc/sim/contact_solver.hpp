// Accelerations with the contact forces of paper 000 Section 5 applied at the contact points
// C_k = p_fk − r ẑ_C (Eqs. 32-33: the force at the foot point plus its moment) and friction from
// v_Ck (Eq. 38), stepped explicitly or linearly implicitly:
//   a = a₀ + M⁻¹ J_Cᵀ f,   a₀ = M⁻¹(Sᵀτ − c − g)   (Eq. 30 split by linearity in f; one Cholesky
//   factor of M serves both)
// The implicit friction picks each tangential component so that the slip velocity one step ahead,
//   u = J_C (v + dt a₀) + dt Φ f,   Φ = J_C M⁻¹ J_Cᵀ   (contact-space inverse inertia),
// satisfies f_t = −μ(u) f_n (backward Euler on the friction only; normal forces stay explicit),
// by Gauss-Seidel sweeps over the feet and axes. This keeps Table I's v_s = 0.1 mm/s stable at
// dt = 1e-4 s, where the explicit law needs dt < ~3e-8 s on the light shank (docs/simulator.md).
#pragma once

#include <vector>

#include "rbdc/sim/contact.hpp"
#include "rbdc/sim/dynamics.hpp"

namespace rbdc::sim {

class ContactSolver {
 public:
  /// Fills p_feet, v_feet (foot points, 3 × n_feet), contacts (forces at the contact points),
  /// f_feet (world forces) and a (nv).
  void accelerations(DynamicsModel& dynamics, const ContactParameters& p, const GroundPlane& ground,
                     double dt, const VectorX& q, const Eigen::Ref<const VectorX>& v, const VectorX& tau,
                     Matrix3X& p_feet, Matrix3X& v_feet, std::vector<FootContact>& contacts,
                     Matrix3X& f_feet, VectorX& a);

  /// When on, dynamics_seconds accumulates the wall time of the dynamics calls (forward dynamics,
  /// M and its factor, feet Jacobians); the rest of a call is contact work.
  bool timing = false;
  double dynamics_seconds = 0;

 private:
  void implicit_friction_sweeps(const ContactParameters& p, double dt);

  std::vector<int> active_;      // feet in contact, in order
  MatrixX M_, J_, Jw_, JC_, X_, Phi_;
  Eigen::LLT<MatrixX> llt_;
  VectorX f_, u_base_, rhs_;
};

}  // namespace rbdc::sim
