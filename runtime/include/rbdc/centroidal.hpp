// Centre of mass and centroidal momentum (Orin, Goswami & Lee 2013, "Centroidal dynamics of a
// humanoid robot", Auton. Robots 35), in world axes; docs/conventions.md, "Centroidal quantities".
// The mass counts every body and every rotor (a point mass at its origin on the carrier λ(i));
// armature is reflected inertia on M's diagonal, not a body, and does not enter. h_G = (k_G; l):
// angular momentum about the CoM, then linear momentum, world axes (Featherstone's force order).
// Every function checks its argument sizes and throws std::invalid_argument on a mismatch.
#pragma once

#include "rbdc/data.hpp"

namespace rbdc {

/// c = Σ m_i c_i / m and ċ = Σ m_i ċ_i / m, body by body (c_i: body i's COM in the world, ċ_i its
/// velocity (R_i^W (v_i,O + ω_i × com_i))). q: nq, v: nv. Fills data.com, data.com_velocity;
/// returns data.com.
const Vector3& center_of_mass(const Model& model, Data& data, const VectorRef& q, const VectorRef& v);

/// J_c = Σ m_i R_i^W [-c̃_i 1] J_i / m (3 × nv), J_i body i's Jacobian (Eq. B3) and c_i its COM in
/// body coordinates, so ċ = J_c v. q: nq. Returns data.com_jacobian.
const Matrix3X& center_of_mass_jacobian(const Model& model, Data& data, const VectorRef& q);

/// A_G (6 × nv), h_G = A_G v (Orin et al. 2013, Eq. 25, from the composite inertias of Alg. 5):
/// column block of joint j = X*_j^G I_cj S_j (a floating base's 6 columns: X*_0^G I_c0), plus, with
/// rotors, X*_λ(j)^G X_rotᵀ I_rot S_rot for rotor j's spin; X*_j^G = [1 -c̃; 0 1] (X_W^j)ᵀ moves a
/// wrench from body j to the CoM in world axes. q: nq. Also computes M (data.M, data.Ic).
/// Returns data.A_G.
const Matrix6X& centroidal_momentum_matrix(const Model& model, Data& data, const VectorRef& q);

/// Ȧ_G v (6): ḣ_G at a = 0 (Orin et al. 2013, Eq. 26). ḣ_G is the sum of the bodies' net wrenches
/// f_i = I_i a_i + v_i ×* I_i v_i moved to the CoM (the CoM's own motion drops out: ċ × m ċ = 0); at
/// a = 0 these are the wrenches of the quadratic-velocity pass (Alg. 2), which leaves their sum at
/// the root, f_0. So Ȧ_G v = X*_0^G f_0. q: nq, v: nv. Returns data.centroidal_bias.
const Vector6& centroidal_bias(const Model& model, Data& data, const VectorRef& q, const VectorRef& v);

}  // namespace rbdc
