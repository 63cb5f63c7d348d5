// The rule that decides whether a model's mass matrix is singular (docs/model.md, "Singular mass
// matrix"); the generator applies the same rule (generator/rbdcgen/singular_mass.py).
#pragma once

#include <string>

#include "rbdc/model.hpp"

namespace rbdc {

/// Pivot tolerance of the rule: M is singular when a pivot of M = Lᵀ D L (factored from the last
/// dof to the first, as the generated factor is) has D_k ≤ kSingularPivot · M_kk.
inline constexpr double kSingularPivot = 1e-12;

/// M at one generic configuration (floating base at the identity; joint k, counted from 0 over
/// q's joint entries, at sin(k + 1)), factored as above. Returns "" when every pivot passes, else
/// why M is singular, naming the first failing dof's joint (and its body when that is a massless
/// leaf). Kinematics and inverse dynamics do not need M⁻¹; forward dynamics, its derivatives and
/// the OSC functions refuse a model for which this is not "" (Model::singular_mass_matrix).
std::string mass_matrix_singularity(const Model& model);

}  // namespace rbdc
