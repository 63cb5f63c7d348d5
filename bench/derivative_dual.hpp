// dual_ad (derivative_cases.hpp): the generated PRIMAL code on forward-mode dual numbers. A
// quantity's directions (q tangents, then the plain inputs it differentiates) go through in chunks
// of kChunk per primal call, as chunked forward-mode AD tools do: Dual<kChunk> keeps each operation
// a short vector loop, and one instantiation per primal function keeps the translation unit quick to
// compile (Dual<60> of the Mini Cheetah's forward dynamics alone took over 10 CPU minutes at -O3).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "derivative_cases.hpp"
#include "derivative_errors.hpp"
#include "rbdc/manifold.hpp"
#include "rbdc_test/dual.hpp"

namespace rbdc_bench::derivatives {

constexpr int kChunk = 12;
using Dual = rbdc_test::Dual<kChunk>;

template <class Api>
struct DualWork {
  explicit DualWork(const rbdc::Model& m) : model(m) {}
  rbdc::Model model;
  rbdc::MatrixX T = rbdc::MatrixX::Zero(Api::nq, Api::nv);  ///< ∂(q ⊕ δ)/∂δ
  std::vector<Dual> q = std::vector<Dual>(Api::nq), out = std::vector<Dual>(std::max(Api::nv, 3 * Api::n_feet));
  std::array<std::vector<Dual>, kInputs> x = {std::vector<Dual>(Shape<Api>::input_size[kV]),
                                              std::vector<Dual>(Shape<Api>::input_size[kA]),
                                              std::vector<Dual>(Shape<Api>::input_size[kTau]),
                                              std::vector<Dual>(Shape<Api>::input_size[kF])};
};

/// `quantity`'s block at s: direction d of the chunk starting at `first` is seeded as tangent
/// d - first (q: the column of ∂(q ⊕ δ)/∂δ; a plain input entry: a unit tangent).
template <class Api, Quantity quantity>
void dual_columns(DualWork<Api>& w, const State& s, double* block) {
  constexpr int rows = Shape<Api>::rows(quantity), columns = Shape<Api>::columns(quantity);
  rbdc::tangent_map(w.model, s.q, w.T);
  const std::array<const double*, kInputs> value = {s.v.data(), s.a.data(), s.tau.data(), s.f.data()};
  for (int first = 0; first < columns; first += kChunk) {
    const int n = std::min(kChunk, columns - first);
    for (int i = 0; i < Api::nq; ++i) {
      w.q[i] = Dual(s.q[i]);
      for (int k = 0; k < n && first + k < Api::nv; ++k) w.q[i].d[k] = w.T(i, first + k);
    }
    int direction = Api::nv;  // the first direction of the next differentiated input
    for (int input = 0; input < kInputs; ++input) {
      const int size = Shape<Api>::input_size[input];
      for (int i = 0; i < size; ++i) w.x[input][i] = Dual(value[input][i]);
      if (!differentiates(quantity, input)) continue;
      for (int i = 0; i < size; ++i) {
        const int k = direction + i - first;
        if (k >= 0 && k < n) w.x[input][i].d[k] = 1.0;
      }
      direction += size;
    }
    primal<Api, quantity>(Pointers<Dual>{w.q.data(), {w.x[kV].data(), w.x[kA].data(), w.x[kTau].data(),
                                                      w.x[kF].data()}},
                          w.out.data());
    for (int k = 0; k < n; ++k)
      for (int r = 0; r < rows; ++r) block[(first + k) * rows + r] = w.out[r].d[k];
  }
}

template <class Api>
struct DualContext {
  explicit DualContext(const LoadedRobot& loaded) : work(loaded.model), states(loaded.states) {}
  DualWork<Api> work;
  std::vector<State> states;
  std::vector<double> block = std::vector<double>(Shape<Api>::size(Quantity::forward_dynamics));
};

template <class Api, Quantity quantity>
void call_dual(void* context, int k) {
  auto& c = *static_cast<DualContext<Api>*>(context);
  dual_columns<Api, quantity>(c.work, c.states[static_cast<size_t>(k)], c.block.data());
}

template <class Api>
void add_dual(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<DualContext<Api>>(loaded);
  add_case(loaded.robot.name, kId, "dual_ad", ctx, call_dual<Api, Quantity::inverse_dynamics>);
  add_case(loaded.robot.name, kFd, "dual_ad", ctx, call_dual<Api, Quantity::forward_dynamics>);
}

template <class Api>
Evaluate evaluate_dual(const rbdc::Model& model) {
  check_dimensions<Api>(model);
  return evaluate_columns<Api>(std::make_shared<DualWork<Api>>(model),
                               [](auto constant, DualWork<Api>& work, const State& s, double* block) {
                                 dual_columns<Api, decltype(constant)::value>(work, s, block);
                               });
}

template <class Api>
bool register_dual() {
  register_provider(provide<Api, add_dual<Api>>);
  return register_error_variant(Api::name, "dual_ad", evaluate_dual<Api>);
}

}  // namespace rbdc_bench::derivatives
