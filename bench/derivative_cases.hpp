// Derivatives of the dynamics (issue 12) for every bundled robot with a derivatives scene:
// rbdc-bench-derivatives times the quantities "inverse_dynamics_derivatives" (∂τ/∂q, ∂τ/∂v) and
// "forward_dynamics_derivatives" (∂a/∂q, ∂a/∂v, ∂a/∂τ, ∂a/∂f), and rbdc-derivative-error-study
// measures all six quantities (derivative_quantities.hpp) against the generated code in __float128.
// Both are built from one translation unit per robot and implementation, written by CMake from
// derivative_robot.cpp.in, so that the long generated functions compile in parallel:
//   generated_double, generated_float   the generated derivative code (derivative_generated.hpp)
//   generated_double_xW                 the same on Batch<double>, time per call of W states (W = 8
//                                       with AVX-512)
//                                       (derivative_batch.hpp; timed only)
//   dual_ad                             the generated PRIMAL code on forward-mode duals, 12
//                                       directions per call (derivative_dual.hpp)
//   runtime, finite_differences         rbdc/derivatives.hpp; central differences of the generated
//                                       primal in double; and the primal calls the derivative times
//                                       are quoted against (derivative_references.hpp)
//   reference                           the generated derivative code in __float128, the error
//                                       study's reference (derivative_reference.hpp; not timed)
#pragma once

#include <stdexcept>
#include <string>

#include "derivative_quantities.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench::derivatives {

constexpr const char* kId = "inverse_dynamics_derivatives";
constexpr const char* kFd = "forward_dynamics_derivatives";

/// Throws unless the model has the generated code's dimensions.
template <class Api>
void check_dimensions(const rbdc::Model& model) {
  if (model.nq != Api::nq || model.nv != Api::nv || static_cast<int>(model.feet.size()) != Api::n_feet)
    throw std::runtime_error(std::string("generated/") + Api::name +
                             "/derivatives does not match the robot (run tools/regenerate)");
}

/// The provider that adds `add`'s cases for Api's robot.
template <class Api, void (*add)(const LoadedRobot&)>
void provide() {
  for_each_loaded_robot(
      "derivatives",
      [](const LoadedRobot& loaded) {
        check_dimensions<Api>(loaded.model);
        add(loaded);
      },
      Api::name);
}

/// The inputs of state k of a state set.
template <class T>
Pointers<T> state_pointers(const StateArrays<T>& s, int k) {
  return {s.q_at(k), {s.v_at(k), s.a_at(k), s.tau_at(k), s.f_at(k)}};
}

}  // namespace rbdc_bench::derivatives
