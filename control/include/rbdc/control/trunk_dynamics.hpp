// Where the controller's trunk dynamics come from: the generated recursions for the Mini Cheetah.
//  - closed chain (paper 001 Table 2, Eq. 48): generated/mini_cheetah/stance_osc_lf_rh and
//    stance_osc_rf_lh, the stance pair's two feet pinned by the big-ground-inertia approximation;
//    no contact forces needed.
//  - open chain (Table 1, Eq. 28 / Eq. 50): generated/mini_cheetah/limb_lanes osc_open_chain_lanes
//    (the legs in SIMD lanes; equals full's osc_open_chain) with the contact forces measured by the
//    simulator.
#pragma once

#include "rbdc/control/mini_cheetah.hpp"

namespace rbdc::control {

/// Eq. 58 for the Mini Cheetah: M_ground = m_min / √ε_mach with m_min = 0.064 kg (the shank).
double mini_cheetah_ground_mass();

/// Λ̃, J̃ᵀ, b̃ with the feet of `pair` in contact, from the generated closed-chain recursion.
void closed_chain_dynamics(const double* q, const double* v, StancePair pair, double ground_mass,
                           TrunkTaskDynamics& out);

/// Λ, J̄ᵀ, b with measured foot forces f (world, ground on robot), from the generated open-chain
/// recursion; b includes the forces (Eq. 27).
void open_chain_dynamics(const double* q, const double* v, const FeetForces& f, TrunkTaskDynamics& out);

}  // namespace rbdc::control
