// Mimic couplings (docs/model.md, "Mimic joints"): q_f = m·q_l + o removes the follower's coordinate.
// The tree algorithms keep working in the tree's coordinates; this maps between those and the
// independent ones (the tree's without the followers', order kept) and projects the dynamics:
//   q_tree = expand(q),  v_tree = G v,  a_tree = G a   (G constant: no G-dot term in a_tree)
//   M' = Gᵀ M G,  c' = Gᵀ c,  g' = Gᵀ g,  τ_e' = Gᵀ τ_e,  τ' = Gᵀ τ,  J' = J G
// Each function allocates; models without couplings give G = I.
#pragma once

#include <vector>

#include "rbdc/data.hpp"

namespace rbdc {

/// Where the independent coordinates sit.
struct CoupledCoordinates {
  int nq = 0;  ///< independent configuration size
  int nv = 0;  ///< independent velocity size
  std::vector<int> q_index;  ///< per joint: its coordinate (a follower: its leader's) in q
  std::vector<int> v_index;  ///< per joint: the same in v
  std::vector<bool> follower;  ///< per joint: coupled to a leader
  int num_joints() const;    ///< independent 1-DoF joints (the actuated ones)
};

CoupledCoordinates coupled_coordinates(const Model& model);

/// G, nv × nv': column k of the tree velocity for a unit independent velocity k.
MatrixX coupling_matrix(const Model& model);

/// The tree configuration of independent q (nq' entries): followers at m·q_leader + o.
VectorX expand_configuration(const Model& model, const VectorRef& q);

/// The independent configuration of a tree configuration (drops the followers' entries).
VectorX independent_configuration(const Model& model, const VectorRef& q_tree);

/// The independent velocity (or acceleration) of a tree one (drops the followers' entries).
VectorX independent_velocity(const Model& model, const VectorRef& v_tree);

/// Forward dynamics of the coupled model: a' = M'⁻¹(S'ᵀτ' + Gᵀτ_e − Gᵀ(c + g)), q: nq', v: nv',
/// tau: the independent joints' efforts, f_world: 3 × n_feet. NaN when M' is not positive
/// definite. Uses data for the tree quantities.
VectorX coupled_forward_dynamics(const Model& model, Data& data, const VectorRef& q, const VectorRef& v,
                                 const VectorRef& tau, const Matrix3X& f_world);

}  // namespace rbdc
