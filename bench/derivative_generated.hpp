// The generated derivative code in scalar T (derivative_cases.hpp): generated_double and
// generated_float, timed and error-studied, and (T = __float128, derivative_reference.hpp) the error
// study's reference.
#pragma once

#include <memory>
#include <type_traits>
#include <vector>

#include "derivative_cases.hpp"
#include "derivative_errors.hpp"

namespace rbdc_bench::derivatives {

template <class Api, class T>
struct GeneratedContext {
  StateArrays<T> s;
  std::vector<T> block = std::vector<T>(Shape<Api>::size(Quantity::forward_dynamics));  ///< the largest
};

template <class Api, class T, Quantity quantity>
void call_generated(void* context, int k) {
  auto& c = *static_cast<GeneratedContext<Api, T>*>(context);
  generated<Api, quantity>(state_pointers(c.s, k), c.block.data());
}

template <class T>
const char* generated_name() {
  return std::is_same_v<T, float> ? "generated_float" : "generated_double";
}

template <class Api, class T>
void add_generated(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<GeneratedContext<Api, T>>();
  ctx->s = to_arrays<T>(loaded.states);
  add_case(loaded.robot.name, kId, generated_name<T>(), ctx, call_generated<Api, T, Quantity::inverse_dynamics>);
  add_case(loaded.robot.name, kFd, generated_name<T>(), ctx, call_generated<Api, T, Quantity::forward_dynamics>);
}

template <class Api, class T>
Evaluate evaluate_generated(const rbdc::Model& model) {
  check_dimensions<Api>(model);
  return [](Quantity quantity, const State& s, std::vector<long double>& block) {
    const StateArrays<T> x = to_arrays<T>({s});
    dispatch(quantity, [&](auto constant) {
      constexpr Quantity q = decltype(constant)::value;
      std::vector<T> out(static_cast<size_t>(Shape<Api>::size(q)));
      generated<Api, q>(state_pointers(x, 0), out.data());
      assign_block(out.data(), Shape<Api>::size(q), block);
    });
  };
}

/// Registers the timed cases and the error-study variant of the generated code in T.
template <class Api, class T>
bool register_generated() {
  register_provider(provide<Api, add_generated<Api, T>>);
  return register_error_variant(Api::name, generated_name<T>(), evaluate_generated<Api, T>);
}

}  // namespace rbdc_bench::derivatives
