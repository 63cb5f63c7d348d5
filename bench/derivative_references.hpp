// runtime and finite_differences (derivative_cases.hpp), timed and error-studied, and the primal
// calls the derivative times are quoted against (inverse_dynamics, forward_dynamics;
// generated_double from the same derivatives scene).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "derivative_cases.hpp"
#include "derivative_errors.hpp"
#include "derivative_runtime.hpp"
#include "rbdc/manifold.hpp"

namespace rbdc_bench::derivatives {

/// Central differences of the generated primal code in double with step kStep: 2 primal calls per
/// direction, q stepped on the manifold with rbdc::integrate.
constexpr double kStep = 1e-6;

template <class Api>
struct DifferenceWork {
  explicit DifferenceWork(const rbdc::Model& m) : model(m) {}
  rbdc::Model model;
  rbdc::VectorX delta = rbdc::VectorX::Zero(Api::nv), q_plus = rbdc::VectorX::Zero(Api::nq),
                q_minus = rbdc::VectorX::Zero(Api::nq);
  static constexpr int kLargest = std::max(Api::nv, 3 * Api::n_feet);  ///< input or output size
  std::vector<double> input_plus = std::vector<double>(kLargest), input_minus = std::vector<double>(kLargest),
                      plus = std::vector<double>(kLargest), minus = std::vector<double>(kLargest);
};

/// `quantity`'s block at s, column by column.
template <class Api, Quantity quantity>
void central_differences(DifferenceWork<Api>& w, const State& s, double* block) {
  constexpr int rows = Shape<Api>::rows(quantity);
  const Pointers<double> x{s.q.data(), {s.v.data(), s.a.data(), s.tau.data(), s.f.data()}};
  auto difference = [&](const Pointers<double>& plus, const Pointers<double>& minus, double* column) {
    primal<Api, quantity>(plus, w.plus.data());
    primal<Api, quantity>(minus, w.minus.data());
    for (int r = 0; r < rows; ++r) column[r] = (w.plus[r] - w.minus[r]) / (2 * kStep);
  };
  double* column = block;
  for (int j = 0; j < Api::nv; ++j, column += rows) {
    w.delta.setZero();
    w.delta[j] = kStep;
    rbdc::integrate(w.model, s.q, w.delta, w.q_plus);
    w.delta[j] = -kStep;
    rbdc::integrate(w.model, s.q, w.delta, w.q_minus);
    Pointers<double> plus = x, minus = x;
    plus.q = w.q_plus.data();
    minus.q = w.q_minus.data();
    difference(plus, minus, column);
  }
  for (int input = 0; input < kInputs; ++input) {
    if (!differentiates(quantity, input)) continue;
    const int size = Shape<Api>::input_size[input];
    std::copy(x.x[input], x.x[input] + size, w.input_plus.begin());
    std::copy(x.x[input], x.x[input] + size, w.input_minus.begin());
    Pointers<double> plus = x, minus = x;
    plus.x[input] = w.input_plus.data();
    minus.x[input] = w.input_minus.data();
    for (int i = 0; i < size; ++i, column += rows) {
      w.input_plus[i] += kStep;
      w.input_minus[i] -= kStep;
      difference(plus, minus, column);
      w.input_plus[i] = w.input_minus[i] = x.x[input][i];
    }
  }
}

/// Contexts of the timed cases: the robot's states and the implementation's workspace.
template <class Work>
struct ReferenceContext {
  ReferenceContext(const LoadedRobot& loaded, int block_size)
      : work(loaded.model), states(loaded.states), block(static_cast<size_t>(block_size)) {}
  Work work;
  std::vector<State> states;
  std::vector<double> block;
  const State& at(int k) const { return states[static_cast<size_t>(k)]; }
};

template <class Api, Quantity quantity>
void call_differences(void* context, int k) {
  auto& c = *static_cast<ReferenceContext<DifferenceWork<Api>>*>(context);
  central_differences<Api, quantity>(c.work, c.at(k), c.block.data());
}

template <Quantity quantity>
void call_runtime(void* context, int k) {
  auto& c = *static_cast<ReferenceContext<RuntimeWork>*>(context);
  runtime_columns(c.work, quantity, c.at(k), c.block.data());
}

template <class Api, Quantity quantity>
void call_primal(void* context, int k) {
  auto& c = *static_cast<ReferenceContext<RuntimeWork>*>(context);
  const State& s = c.at(k);
  primal<Api, quantity>(Pointers<double>{s.q.data(), {s.v.data(), s.a.data(), s.tau.data(), s.f.data()}},
                        c.block.data());
}

template <class Api>
void add_references(const LoadedRobot& loaded) {
  using Q = Quantity;
  const std::string& robot = loaded.robot.name;
  const int size = Shape<Api>::size(Q::forward_dynamics);
  auto runtime = std::make_shared<ReferenceContext<RuntimeWork>>(loaded, size);
  add_case(robot, "inverse_dynamics", "generated_double", runtime, call_primal<Api, Q::inverse_dynamics>);
  add_case(robot, "forward_dynamics", "generated_double", runtime, call_primal<Api, Q::forward_dynamics>);
  add_case(robot, kId, "runtime", runtime, call_runtime<Q::inverse_dynamics>);
  add_case(robot, kFd, "runtime", runtime, call_runtime<Q::forward_dynamics>);
  auto differences = std::make_shared<ReferenceContext<DifferenceWork<Api>>>(loaded, size);
  add_case(robot, kId, "finite_differences", differences, call_differences<Api, Q::inverse_dynamics>);
  add_case(robot, kFd, "finite_differences", differences, call_differences<Api, Q::forward_dynamics>);
}

template <class Api>
Evaluate evaluate_differences(const rbdc::Model& model) {
  check_dimensions<Api>(model);
  return evaluate_columns<Api>(std::make_shared<DifferenceWork<Api>>(model),
                               [](auto constant, DifferenceWork<Api>& work, const State& s, double* block) {
                                 central_differences<Api, decltype(constant)::value>(work, s, block);
                               });
}

inline Evaluate evaluate_runtime(const rbdc::Model& model) {
  auto work = std::make_shared<RuntimeWork>(model);
  return [work](Quantity quantity, const State& s, std::vector<long double>& block) {
    const int size = parts(quantity, work->model.nv, static_cast<int>(s.tau.size()),
                           static_cast<int>(s.f.cols())).back().end;
    std::vector<double> out(static_cast<size_t>(size));
    runtime_columns(*work, quantity, s, out.data());
    assign_block(out.data(), size, block);
  };
}

template <class Api>
bool register_references() {
  register_provider(provide<Api, add_references<Api>>);
  register_error_variant(Api::name, "runtime", evaluate_runtime);
  return register_error_variant(Api::name, "finite_differences", evaluate_differences<Api>);
}

}  // namespace rbdc_bench::derivatives
