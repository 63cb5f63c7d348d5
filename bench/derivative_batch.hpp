// generated_double_xW (derivative_cases.hpp): the generated derivative code on Batch<double>, states
// packed W at a time as in batch_cases.cpp (W = 8 with AVX-512); a call evaluates W states. Timed
// only (its lanes compute what generated_double computes).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "derivative_cases.hpp"
#include "rbdc_gen/batch.hpp"

namespace rbdc_bench::derivatives {

template <class Api>
struct BatchContext {
  using P = rbdc_gen::Batch<double>;
  static constexpr int kGroups = kStateCount / P::lanes;
  StateArrays<P> packs;  ///< kGroups packed states
  std::vector<P> block = std::vector<P>(Shape<Api>::size(Quantity::forward_dynamics));
  explicit BatchContext(const StateArrays<double>& s) {
    auto pack = [](const std::vector<double>& states, int size, std::vector<P>& packed) {
      packed.resize(static_cast<size_t>(kGroups * size));
      for (int g = 0; g < kGroups; ++g) {
        rbdc_gen::pack_states(states.data() + static_cast<size_t>(g * P::lanes * size), size, size,
                              packed.data() + static_cast<size_t>(g * size));
      }
    };
    packs.count = kGroups;
    packs.nq = s.nq;
    packs.nv = s.nv;
    packs.n_joints = s.n_joints;
    packs.n_feet = s.n_feet;
    pack(s.q, s.nq, packs.q);
    pack(s.v, s.nv, packs.v);
    pack(s.a, s.nv, packs.a);
    pack(s.tau, s.n_joints, packs.tau);
    pack(s.f, 3 * s.n_feet, packs.f);
  }
};

template <class Api, Quantity quantity>
void call_batch(void* context, int k) {
  auto& c = *static_cast<BatchContext<Api>*>(context);
  generated<Api, quantity>(state_pointers(c.packs, k & (BatchContext<Api>::kGroups - 1)), c.block.data());
}

template <class Api>
void add_batch(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<BatchContext<Api>>(to_arrays<double>(loaded.states));
  const std::string implementation = "generated_double_x" + std::to_string(BatchContext<Api>::P::lanes);
  add_case(loaded.robot.name, kId, implementation, ctx, call_batch<Api, Quantity::inverse_dynamics>);
  add_case(loaded.robot.name, kFd, implementation, ctx, call_batch<Api, Quantity::forward_dynamics>);
}

template <class Api>
bool register_batch() {
  return register_provider(provide<Api, add_batch<Api>>);
}

}  // namespace rbdc_bench::derivatives
