// Rigid-contact dynamics, impulse dynamics at touchdown and the derivatives of the contact dynamics
// (issue 21) for a set of point contacts at the feet. Equations: docs/runtime.md, "Contact
// dynamics"; sources: Featherstone, RBDA (2008) ch. 8 (the constrained equation of motion as a KKT system) and
// Carpentier & Mansard, "Analytical derivatives of rigid body dynamics algorithms", RSS 2018
// (differentiating the KKT system through its inverse).
//
// A contact set is a list of feet (indices into model.feet); contact k holds foot contact_feet[k]
// to a world point: 3 rows of the contact Jacobian J (world coordinates) and 3 entries of λ, the
// world force the ground applies on the foot. Repeating a foot is allowed (a redundant contact).
#pragma once

#include <Eigen/Cholesky>
#include <vector>

#include "rbdc/derivatives.hpp"

namespace rbdc {

/// Baumgarte stabilisation of the contact constraint (Baumgarte 1972): the constraint rows ask
/// J a + J̇v + kd J v + kp (p − p*) = 0 instead of J a + J̇v = 0, so that a drift of the contact
/// velocity (kd, 1/s) or position (kp, 1/s², towards the anchor p*) decays.
struct BaumgarteGains {
  double kp = 0;
  double kd = 0;
};

/// The damping of the contact solve (documented in docs/runtime.md, "Bad input"): the Delassus
/// matrix A = J M⁻¹ Jᵀ is factorised as A + μ1 with μ = kContactDampingRelative · tr(A)/m
/// + kContactDampingFloor (m = rows), and kContactProximalSteps proximal steps
/// λ ← λ + (A + μ1)⁻¹(b − A λ) from λ = 0 solve A λ = b. For a full-rank A they converge to the
/// exact solution (error factor μ/σ_min(A) per step, docs/runtime.md); for a rank-deficient A (redundant contacts)
/// to the least-norm λ, with a unique, finite acceleration. Never NaN for finite input.
inline constexpr double kContactDampingRelative = 1e-5;
inline constexpr double kContactDampingFloor = 1e-30;
inline constexpr int kContactProximalSteps = 5;

/// Results and workspace of the contact algorithms for one contact set; every matrix is sized in
/// the constructor (m = 3 · contact_feet.size() rows), so no call below touches the heap.
struct ContactDynamicsData {
  /// contact_feet: indices into model.feet (repeats allowed, empty allowed). Throws
  /// std::invalid_argument naming the bad index.
  ContactDynamicsData(const Model& model, std::vector<int> contact_feet, BaumgarteGains gains = {});

  std::vector<int> contact_feet;  ///< the contact set: foot index of each contact
  BaumgarteGains gains;           ///< Baumgarte gains of contact_dynamics

  // --- Results -----------------------------------------------------------------------------------
  VectorX a;                ///< contact_dynamics: the acceleration (nv)
  VectorX lambda;           ///< contact_dynamics: contact forces, world, contact-major (m)
  VectorX v_plus;           ///< impulse_dynamics: the velocity after the impact (nv)
  VectorX impulse;          ///< impulse_dynamics: contact impulses, world, contact-major (m)
  MatrixX da_dq;            ///< contact_dynamics_derivatives: ∂a/∂q on the manifold (nv × nv)
  MatrixX da_dv;            ///< ∂a/∂v (nv × nv)
  MatrixX da_dtau;          ///< ∂a/∂τ (nv × n_joints)
  MatrixX dlambda_dq;       ///< ∂λ/∂q on the manifold (m × nv)
  MatrixX dlambda_dv;       ///< ∂λ/∂v (m × nv)
  MatrixX dlambda_dtau;     ///< ∂λ/∂τ (m × n_joints)

  // --- Workspace -----------------------------------------------------------------------------------
  MatrixX J;                ///< contact Jacobian, world (m × nv)
  VectorX gamma;            ///< J̇v + Baumgarte terms (m); impulse: (1 + e) J v⁻
  MatrixX Minv_Jt;          ///< M⁻¹Jᵀ (nv × m)
  MatrixX A;                ///< Delassus matrix J M⁻¹ Jᵀ (m × m)
  double mu = 0;            ///< the damping of the last factorisation
  Eigen::LLT<MatrixX> A_llt;  ///< Cholesky factor of A + μ1
  VectorX rhs;              ///< right-hand side of the current solve (m)
  VectorX step;             ///< proximal step (m)
  Matrix3X f_feet;          ///< λ summed per foot (3 × n_feet), for ∂(Jᵀλ)/∂q
  MatrixX r_joint;          ///< ∂(KKT row 1)/∂(q or v) at fixed (a, λ) (nv × nv)
  MatrixX r_contact;        ///< ∂(KKT row 2)/∂(q or v) at fixed a (m × nv)
  MatrixX r_tau;            ///< ∂(KKT row 1)/∂τ = −Sᵀ (nv × n_joints)
  MatrixX dpddot_dq;        ///< ∂(contact classical accelerations at fixed a)/∂q (m × nv)
  MatrixX dpddot_dv;        ///< ∂(the same)/∂v (m × nv)
  MatrixX dpdot_dq;         ///< ∂(contact velocities)/∂q (m × nv)
  MatrixX dp_dq;            ///< ∂(contact positions)/∂q (m × nv)
};

/// Contact dynamics: a and λ of the KKT system (RBDA ch. 8)
///   M a − Jᵀλ = Sᵀτ − c − g,   J a = −J̇v − kd J v − kp (p − anchors)
/// solved through its Schur complement: a₀ = M⁻¹(Sᵀτ − c − g), (J M⁻¹Jᵀ) λ = −(J a₀ + γ),
/// a = a₀ + M⁻¹Jᵀλ (with the damping above). q: nq, v: nv, tau: n_joints. Without contacts,
/// a is the forward dynamics. This overload needs gains.kp = 0 (else it throws). Returns contact.a;
/// λ in contact.lambda. If M is not positive definite every entry of a and λ is NaN.
const VectorX& contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v, const VectorRef& tau);

/// The same with the position anchors p* of the Baumgarte term: anchors is 3 × n_contacts, world.
const VectorX& contact_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v, const VectorRef& tau,
                                const Matrix3X& anchors);

/// Impulse dynamics of a touchdown with restitution e ∈ [0, 1] (RBDA ch. 11, impact):
///   M (v⁺ − v⁻) = Jᵀ Λ,   J v⁺ = −e J v⁻,
/// so (J M⁻¹Jᵀ) Λ = −(1 + e) J v⁻ and v⁺ = v⁻ + M⁻¹JᵀΛ. q: nq, v_minus: nv. Returns contact.v_plus;
/// the impulses in contact.impulse. Throws for e outside [0, 1] or not finite.
const VectorX& impulse_dynamics(const Model& model, Data& data, ContactDynamicsData& contact,
                                const VectorRef& q, const VectorRef& v_minus, double restitution);

/// ∂(a, λ)/∂(q, v, τ) of contact_dynamics (q on the manifold, like derivatives.hpp), by
/// differentiating both KKT rows at the solution (Carpentier & Mansard 2018):
///   [M −Jᵀ; J 0] [∂a; ∂λ] = −[∂(ID(q, v, a) − Jᵀλ − Sᵀτ); ∂(J a + γ)] at fixed (a, λ),
/// solved as ∂λ = A⁻¹(J M⁻¹ r₁ − r₂), ∂a = M⁻¹(Jᵀ∂λ − r₁). Fills contact.a, λ and the six
/// derivatives; uses derivatives as tangent-pass workspace. Anchors as in contact_dynamics.
void contact_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  ContactDynamicsData& contact, const VectorRef& q,
                                  const VectorRef& v, const VectorRef& tau);
void contact_dynamics_derivatives(const Model& model, Data& data, DerivativeData& derivatives,
                                  ContactDynamicsData& contact, const VectorRef& q,
                                  const VectorRef& v, const VectorRef& tau, const Matrix3X& anchors);

}  // namespace rbdc
