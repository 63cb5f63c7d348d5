// The generated derivative code on Batch<double>: states packed 8 at a time, as in batch_cases.cpp
// (derivative_cases.hpp).
#include <memory>
#include <vector>

#include "derivative_cases.hpp"
#include "rbdc_gen/batch.hpp"
#include "registry.hpp"

namespace rbdc_bench::derivatives {
namespace {

struct BatchContext {
  using P = rbdc_gen::Batch<double>;
  static constexpr int kGroups = kStateCount / P::lanes;
  std::vector<P> q, v, a, tau, f;
  Outputs<P> out;
  explicit BatchContext(const StateArrays<double>& s) {
    auto pack = [](const std::vector<double>& states, int size, std::vector<P>& packs) {
      packs.resize(static_cast<size_t>(kGroups * size));
      for (int g = 0; g < kGroups; ++g) {
        rbdc_gen::pack_states(states.data() + static_cast<size_t>(g * P::lanes * size), size, size,
                              packs.data() + static_cast<size_t>(g * size));
      }
    };
    pack(s.q, nq, q);
    pack(s.v, nv, v);
    pack(s.a, nv, a);
    pack(s.tau, nj, tau);
    pack(s.f, 3 * nf, f);
  }
  const P* at(const std::vector<P>& x, int size, int state) const {
    return x.data() + static_cast<size_t>((state & (kGroups - 1)) * size);
  }
};

}  // namespace

void add_generated_batch(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<BatchContext>(to_arrays<double>(loaded.states));
  add_case(loaded.robot.name, kId, "generated_double_x8", ctx, [](void* p, int k) {
    BatchContext& c = *static_cast<BatchContext*>(p);
    mc::inverse_dynamics_derivatives(c.at(c.q, nq, k), c.at(c.v, nv, k), c.at(c.a, nv, k),
                                     c.out.dq.data(), c.out.dv.data());
  });
  add_case(loaded.robot.name, kFd, "generated_double_x8", ctx, [](void* p, int k) {
    BatchContext& c = *static_cast<BatchContext*>(p);
    mc::forward_dynamics_derivatives(c.at(c.q, nq, k), c.at(c.v, nv, k), c.at(c.tau, nj, k),
                                     c.at(c.f, 3 * nf, k), c.out.dq.data(), c.out.dv.data(),
                                     c.out.dtau.data(), c.out.df.data());
  });
}

}  // namespace rbdc_bench::derivatives
