// The runtime's analytic derivatives (rbdc/derivatives.hpp) as blocks (derivative_quantities.hpp).
#pragma once

#include "derivative_quantities.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc_bench/random_states.hpp"

namespace rbdc_bench::derivatives {

struct RuntimeWork {
  explicit RuntimeWork(const rbdc::Model& m) : model(m), data(model), derivatives(model) {}
  rbdc::Model model;
  rbdc::Data data;
  rbdc::DerivativeData derivatives;
};

/// Runs the runtime's derivative function of `quantity` at s and copies its results into `block`.
void runtime_columns(RuntimeWork& w, Quantity quantity, const State& s, double* block);

}  // namespace rbdc_bench::derivatives
