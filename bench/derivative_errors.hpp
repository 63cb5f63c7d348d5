// The variants rbdc-derivative-error-study compares (derivative_cases.hpp): each translation unit of a
// robot registers how its implementation computes every derivative quantity, as a block in long
// double (derivative_quantities.hpp); "reference" is the generated code in __float128.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "derivative_quantities.hpp"
#include "rbdc_bench/random_states.hpp"

namespace rbdc_bench::derivatives {

/// Writes `quantity`'s block at state s.
using Evaluate = std::function<void(Quantity quantity, const State& s, std::vector<long double>& block)>;
/// Builds an Evaluate for the loaded model (throws if the model does not fit the generated code).
using MakeEvaluate = Evaluate (*)(const rbdc::Model& model);

struct ErrorVariant {
  std::string robot, name;
  MakeEvaluate make;
};

std::vector<ErrorVariant>& error_variants();

/// Static registration; returns a dummy so it can initialise a namespace-scope bool.
bool register_error_variant(const std::string& robot, const std::string& name, MakeEvaluate make);

/// Copies a block of any scalar into long double.
template <class T>
void assign_block(const T* values, int size, std::vector<long double>& block) {
  block.resize(static_cast<size_t>(size));
  for (int i = 0; i < size; ++i) block[static_cast<size_t>(i)] = static_cast<long double>(values[i]);
}

/// An Evaluate for an implementation that fills double blocks: `fill(constant, work, s, block)`
/// with constant = std::integral_constant<Quantity, quantity> (dual_columns, central_differences).
template <class Api, class Work, class Fill>
Evaluate evaluate_columns(std::shared_ptr<Work> work, Fill fill) {
  return [work, fill](Quantity quantity, const State& s, std::vector<long double>& block) {
    dispatch(quantity, [&](auto constant) {
      constexpr int size = Shape<Api>::size(decltype(constant)::value);
      std::vector<double> out(static_cast<size_t>(size));
      fill(constant, *work, s, out.data());
      assign_block(out.data(), size, block);
    });
  };
}

}  // namespace rbdc_bench::derivatives
