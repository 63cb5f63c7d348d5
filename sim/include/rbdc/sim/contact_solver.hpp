// Accelerations with the contact forces of paper 000 Section 5 applied at the contact points
// C_k = p_fk − r ẑ_C (Eqs. 32-33: the force at the foot point plus its moment) and friction from
// v_Ck (Eq. 38), stepped explicitly or linearly implicitly. Eq. 30 is split by linearity in f:
//   a = a₁ + M⁻¹ J_Tᵀ f_t,   a₁ = a₀ + M⁻¹ J_Cᵀ f_known,   a₀ = M⁻¹(Sᵀτ − c − g)
// with f_known the explicit normal forces (and the friction, when it is explicit) and J_T the
// tangential rows of J_C; one sparse factor M = Lᵀ D L of the tree (tree_ltdl.hpp) serves both.
// The feet, their rows, the factor and a₀ come from one DynamicsModel::step_terms call.
// The implicit friction picks each tangential component so that the slip velocity one step ahead,
//   u = J_T (v + dt a₁) + dt Φ f_t,   Φ = J_T M⁻¹ J_Tᵀ   (contact-space inverse inertia),
// satisfies f_t = −μ(u) f_n (backward Euler on the friction only; normal forces stay explicit),
// by Gauss-Seidel sweeps over the feet and axes, warm-started from the previous solve, until the
// forces stop changing. With Y = L⁻ᵀ J_Tᵀ, Φ = Yᵀ D⁻¹ Y and M⁻¹ J_Tᵀ f_t = L⁻¹ D⁻¹ (Y f_t); only
// the feet in contact are solved for, and the work arrays are sized once (no allocation in a
// step). This keeps Table I's v_s = 0.1 mm/s stable at dt = 1e-4 s, where the explicit law needs
// dt < ~3e-8 s on the light shank (docs/simulator.md).
#pragma once

#include <optional>
#include <vector>

#include "rbdc/sim/contact.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

namespace rbdc::sim {

class ContactSolver {
 public:
  /// Fills p_feet, v_feet (foot points, 3 × n_feet), contacts (forces at the contact points),
  /// f_feet (world forces) and a (nv).
  void accelerations(DynamicsModel& dynamics, const ContactParameters& p, const GroundPlane& ground,
                     double dt, const VectorX& q, const Eigen::Ref<const VectorX>& v, const VectorX& tau,
                     Matrix3X& p_feet, Matrix3X& v_feet, std::vector<FootContact>& contacts,
                     Matrix3X& f_feet, VectorX& a);

  /// When on, dynamics_seconds accumulates the wall time of the dynamics call (step_terms: feet,
  /// their rows, M's factor, a₀); the rest of a call is contact work.
  bool timing = false;
  double dynamics_seconds = 0;

 private:
  /// Sizes the work arrays for `dynamics` (once, or when the robot changes).
  void prepare(DynamicsModel& dynamics);
  /// Tangential forces f_ (2 per foot in contact) for the normal forces in `contacts`.
  void implicit_friction_sweeps(const ContactParameters& p, double dt, const std::vector<FootContact>& contacts);

  std::vector<int> active_;  // feet in contact, in order
  std::optional<TreeLtdl> ltdl_;
  StepTerms terms_;
  MatrixX JC_, JT_, Y_, DY_, Phi_;  // J_C, J_T (its x, y rows), Y = L⁻ᵀ J_Tᵀ, D⁻¹Y, Φ:
                                    // first 3m / 2m rows or columns in use
  VectorX f_, u_base_, rhs_, impulse_;
  Eigen::Matrix2Xd last_friction_;  // each foot's friction from the previous solve (zero when not in contact)
};

}  // namespace rbdc::sim
