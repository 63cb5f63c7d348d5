// Feet Jacobian (paper 000 Alg. 6 and App. B).
#pragma once

#include <vector>

#include "rbdc/data.hpp"

namespace rbdc {

/// Alg. 6 in world coordinates: J (3·n_feet × nv), rows 3k…3k+2 map v to foot k's world linear
/// velocity (J v = feet_velocities, Jᵀ f = feet_force_terms). q: nq. Returns data.J.
const MatrixX& feet_jacobian(const Model& model, Data& data, const VectorRef& q);

/// Alg. 6 in contact frames: rows 3k…3k+2 give foot k's linear velocity in contact-frame
/// coordinates, J_C,k = (world_R_contact[k])ᵀ J_k. world_R_contact[k] (n_feet entries) holds
/// the contact frame's axes in world coordinates (R_Ck^W of Eq. 33); the contact point is the
/// foot point. q: nq. Returns data.J_contact.
const MatrixX& feet_jacobian_contact(const Model& model, Data& data, const VectorRef& q,
                                     const std::vector<Matrix3>& world_R_contact);

}  // namespace rbdc
