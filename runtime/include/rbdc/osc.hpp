// Trunk operational-space quantities (paper 001): the O(nd) recursions of Table 1 (open chain,
// measured contact forces) and Table 2 (closed chain, big-ground-inertia approximation), and the
// closed-form numeric references they are checked against.
//
// Task: the trunk (body 0) of a floating-base model. Everything is in trunk coordinates:
//   Λ_t · a_t + b_t = J̄_tᵀ τ + f_t,   a_t = a[0:6] = (ω̇_B, R_W^0 p̈_W),
// f_t a wrench on the trunk at its origin. Because v[0:6] is the trunk twist in trunk coordinates,
// the task Jacobian is the constant selector J_t = [1₆ 0] (J̇_t = 0), and a[0:6] is exactly the
// classical task acceleration ẍ_t = (ω̇, p̈) of paper 001 expressed in trunk coordinates.
// Results go to data.osc (recursions) or reference.result (closed forms, whose workspace is an
// OscReferenceData apart from Data: the recursions never need it). A fixed-base model has
// no trunk task: every function throws std::invalid_argument for it, as for wrong sizes.
#pragma once

#include <vector>

#include "rbdc/data.hpp"

namespace rbdc {

/// Eq. 58: M_ground = m_min / √ε_mach, m_min = the smallest positive body mass of the model.
double default_ground_mass(const Model& model);

/// Table 1 (Eqs. 29-41): Λ_t, J̄_tᵀ and b_t with measured foot forces. q: nq, v: nv,
/// f_feet_world: 3 × n_feet world forces applied to the feet (the ground on the robot).
/// b_t includes gravity, velocity products and the foot forces (Eq. 27).
const OscQuantities& osc_open_chain(const Model& model, Data& data, const VectorRef& q,
                                    const VectorRef& v, const Matrix3X& f_feet_world);

/// Table 1 with Table 2 (Eqs. 42-47): Λ̃_t, J̃_tᵀ, b̃_t with the feet listed in contact_feet
/// (indices into model.feet, no repeats) pinned to the ground by a point mass ground_mass (kg) at
/// each foot. The feet are assumed at rest (J_c v = 0, paper 001 Eq. 16); the result tends to the
/// constrained closed form as ground_mass grows, until round-off takes over (Fig. 7).
const OscQuantities& osc_closed_chain(const Model& model, Data& data, const VectorRef& q,
                                      const VectorRef& v, const std::vector<int>& contact_feet,
                                      double ground_mass);

/// osc_closed_chain with ground_mass = default_ground_mass(model) (Eq. 58).
const OscQuantities& osc_closed_chain(const Model& model, Data& data, const VectorRef& q,
                                      const VectorRef& v, const std::vector<int>& contact_feet);

/// Workspace and result of the closed-form references below, sized once from a Model so that no
/// call touches the heap. They also use Data for H, C, G, J_c and its Cholesky factor of H.
struct OscReferenceData {
  explicit OscReferenceData(const Model& model);

  OscQuantities result;          ///< output of osc_closed_form / osc_closed_form_constrained
  MatrixX M_inv;                 ///< H⁻¹ (nv × nv)
  Matrix6X J_t;                  ///< task Jacobian [1₆ 0] (6 × nv)
  Matrix6X J_t_M_inv;            ///< J_t H⁻¹ (6 × nv)
  Matrix6X J_t_M_inv_N_cT;       ///< J_t H⁻¹ N_cᵀ (6 × nv)
  Matrix6X JbarT_full;           ///< J̄_tᵀ over all of v (6 × nv)
  MatrixX J_c;                   ///< contact Jacobian rows, world (top 3·n_contacts rows used)
  MatrixX J_c_M_inv;             ///< J_c H⁻¹, then J̄_cᵀ = Λ_c J_c H⁻¹ (top rows used)
  MatrixX A_c;                   ///< Λ_c⁻¹ = J_c H⁻¹ J_cᵀ (top-left block used)
  MatrixX N_cT;                  ///< N_cᵀ = 1 - J_cᵀ J̄_cᵀ (nv × nv)
  VectorX contact_bias;          ///< J̇_c v, then Λ_c J̇_c v (top rows used)
  VectorX work_nv;               ///< an nv-vector of scratch
};

/// Closed-form reference for osc_open_chain from H, C, G and J_c (Eqs. 10-13 and 27):
/// Λ_t = (J_t H⁻¹ J_tᵀ)⁻¹, J̄_tᵀ = Λ_t J_t H⁻¹, b_t = J̄_tᵀ (C + G - J_cᵀ F_c). Returns
/// reference.result.
const OscQuantities& osc_closed_form(const Model& model, Data& data, OscReferenceData& reference,
                                     const VectorRef& q, const VectorRef& v,
                                     const Matrix3X& f_feet_world);

/// Closed-form reference for osc_closed_chain, the exact contact-constrained quantities
/// (Eqs. 16-26): N_cᵀ = 1 - J_cᵀ J̄_cᵀ, Λ̃_t = (J_t H⁻¹ N_cᵀ J_tᵀ)⁻¹, J̃_tᵀ = Λ̃_t J_t H⁻¹ N_cᵀ,
/// b̃_t = J̃_tᵀ (C + G) + Λ̃_t J_t H⁻¹ J_cᵀ Λ_c J̇_c v. Returns reference.result.
const OscQuantities& osc_closed_form_constrained(const Model& model, Data& data,
                                                 OscReferenceData& reference, const VectorRef& q,
                                                 const VectorRef& v,
                                                 const std::vector<int>& contact_feet);

}  // namespace rbdc
