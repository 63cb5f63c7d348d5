// The dynamics section of rbdc-info: M, c, g, feet positions and feet Jacobian from the runtime at
// one state, and the documented default state that rbdc-info uses when no --q is given.
#pragma once

#include <ostream>

#include "rbdc/model.hpp"

namespace rbdc::tools {

/// Documented state (docs/runtime.md): a floating base stands at p = (0, 0, 0.3) with the identity
/// orientation; joint j (counted from 0) sits at (0, -0.8, 1.6)[j mod 3], the Mini Cheetah's
/// standing pose of abad, hip and knee.
VectorX documented_configuration(const Model& model);

/// Documented velocity: entry k is 0.1·(k mod 5 + 1)·(-1)^k.
VectorX documented_velocity(const Model& model);

/// Prints M, c, g, the feet positions and the feet Jacobian at (q, v).
void print_dynamics(const Model& model, const VectorX& q, const VectorX& v, std::ostream& out);

}  // namespace rbdc::tools
