// The split RNEA of paper 000 Section 4.1-4.3: quadratic velocity terms c (Alg. 2), gravity terms
// g (Alg. 3) and external wrench terms τ_e (Alg. 4), each an nv-vector with the layout of v.
// Every function runs the kinematics it needs and throws std::invalid_argument on a size mismatch.
#pragma once

#include <vector>

#include "rbdc/data.hpp"

namespace rbdc {

/// Alg. 2: c(q, v), the Coriolis and centrifugal terms. q: nq, v: nv. Returns data.c.
const VectorX& quadratic_velocity_terms(const Model& model, Data& data, const VectorRef& q,
                                        const VectorRef& v);

/// Alg. 3: g(q), gravity entering as the fictitious acceleration a_0 = -(0, R_W^0 g_W).
/// q: nq. Returns data.g.
const VectorX& gravity_terms(const Model& model, Data& data, const VectorRef& q);

/// Alg. 4 in body form: f_ext[i] is the wrench applied to body i, taken at body i's origin and
/// expressed in body i coordinates (nb entries). q: nq. Returns data.tau_e.
const VectorX& external_wrench_terms(const Model& model, Data& data, const VectorRef& q,
                                     const std::vector<Vector6>& f_ext);

/// Alg. 4 for foot forces: column k of f_world (3 × n_feet) is the force applied to foot k's point,
/// in world coordinates. Builds the body wrenches (at F_i = the foot frame, Eq. 16) and runs
/// external_wrench_terms; equals Jᵀ f (App. B). q: nq. Returns data.tau_e.
const VectorX& feet_force_terms(const Model& model, Data& data, const VectorRef& q,
                                const Matrix3X& f_world);

}  // namespace rbdc
