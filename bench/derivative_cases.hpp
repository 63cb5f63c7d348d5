// Derivatives of the dynamics (issue 12) on the Mini Cheetah, quantities
// "inverse_dynamics_derivatives" (∂τ/∂q, ∂τ/∂v) and "forward_dynamics_derivatives" (∂a/∂q, ∂a/∂v,
// ∂a/∂τ, ∂a/∂f), timed by rbdc-bench-derivatives. The implementations are spread over translation
// units that compile in parallel (the generated derivative functions are the slow ones):
//   derivative_double.cpp, derivative_float.cpp   generated_double, generated_float: the generated
//                              derivative code (derivative_generated.hpp)
//   derivative_batch.cpp       generated_double_x8: the same on Batch<double>, time per call of 8 states
//   derivative_dual.cpp        dual_ad: the generated PRIMAL code on forward-mode duals, in chunks of
//                              12 directions per call
//   derivative_cases.cpp       runtime (rbdc/derivatives.hpp), finite_differences (central,
//                              generated primal in double, q stepped with rbdc::integrate),
//                              and the primal calls themselves (inverse_dynamics, forward_dynamics,
//                              generated_double) that the derivative times are quoted against
#pragma once

#include <vector>

#include "mini_cheetah/derivatives.hpp"
#include "robot_states.hpp"

namespace rbdc_bench::derivatives {

namespace mc = rbdc_gen::mini_cheetah::derivatives;
constexpr int nq = mc::nq, nv = mc::nv, nj = mc::n_joints, nf = mc::n_feet;
constexpr const char* kId = "inverse_dynamics_derivatives";
constexpr const char* kFd = "forward_dynamics_derivatives";

/// Outputs large enough for both quantities.
template <class T>
struct Outputs {
  std::vector<T> dq = std::vector<T>(nv * nv), dv = std::vector<T>(nv * nv),
                 dtau = std::vector<T>(nv * nj), df = std::vector<T>(nv * 3 * nf);
};

void add_generated_double(const LoadedRobot& loaded);
void add_generated_float(const LoadedRobot& loaded);
void add_generated_batch(const LoadedRobot& loaded);
void add_dual(const LoadedRobot& loaded);

}  // namespace rbdc_bench::derivatives
