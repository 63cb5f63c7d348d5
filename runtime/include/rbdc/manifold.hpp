// The configuration manifold of docs/conventions.md ("Derivatives on the manifold"): the step
// q ⊕ δ that every derivative with respect to q is taken along, its coordinate Jacobian, and the
// conversion of rbdc's derivatives to Pinocchio's ordering and acceleration convention.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// q_out = q ⊕ δ. Floating base: p' = p + R δp, R' = R exp(δθ^) (R: trunk → world, from the
/// normalised quaternion of q; the result's quaternion is unit), joints q_j' = q_j + δq_j, with
/// δ = (δθ, δp, joint tangents) ordered like v. Fixed base: q' = q + δ.
/// q: nq, delta: nv, q_out: nq (may alias q). Throws std::invalid_argument on a size mismatch.
void integrate(const Model& model, const VectorRef& q, const VectorRef& delta,
               Eigen::Ref<VectorX> q_out);

/// T = ∂(q ⊕ δ)/∂δ at δ = 0 (nq × nv): position rows R (columns δp), quaternion rows
/// ½ q_quat ⊗ (0, e_k) (columns δθ_k), identity for the joints. A derivative in plain coordinates
/// maps to rbdc's by ∂f/∂δ = ∂f/∂q · T. Throws std::invalid_argument on a size mismatch.
void tangent_map(const Model& model, const VectorRef& q, MatrixX& T);

/// T⁺ (nv × nq), the pseudo-inverse of tangent_map for a unit quaternion (position rows Rᵀ,
/// quaternion rows 4·(½ q_quat ⊗ (0, e_k))ᵀ, identity for the joints). For a function that, like
/// every rbdc quantity, depends on the quaternion only through its normalisation:
/// ∂f/∂q = ∂f/∂δ · T⁺ exactly. Throws std::invalid_argument on a size mismatch.
void tangent_map_inverse(const Model& model, const VectorRef& q, MatrixX& T_inverse);

/// Pinocchio orders a free-flyer's velocity (v_B, ω_B), rbdc (ω_B, v_B). Swaps the first three and
/// the next three rows (rows = true) or columns (rows = false) of m in place; a no-op for a fixed
/// base. Apply it to the rows of anything indexed like τ or a and to the columns of anything
/// differentiated with respect to q, v or a. It is its own inverse.
void swap_trunk_angular_linear(const Model& model, MatrixX& m, bool rows);

}  // namespace rbdc
