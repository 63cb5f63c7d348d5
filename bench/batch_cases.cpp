// Generated mini_cheetah code on SIMD batches (rbdc_gen/batch.hpp): one call evaluates
// Batch<double> or Batch<float>, one register of states (8 or 16 with AVX-512). Implementations
// "generated_double_xW" and "generated_float_xW", W the lanes: the time is per call, so per state it
// is that over W (docs/performance.md). The states are the harness's, packed W at a time.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mini_cheetah/full.hpp"
#include "rbdc_gen/batch.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

namespace mc = rbdc_gen::mini_cheetah::full;

template <class T>
struct BatchContext {
  using P = rbdc_gen::Batch<T>;
  static constexpr int kGroups = kStateCount / P::lanes;  ///< power of two: the index wraps by mask
  std::vector<P> q, v, a, tau, f;                         ///< group g at g·size
  std::vector<P> out = std::vector<P>(mc::nv * mc::nv);

  explicit BatchContext(const StateArrays<T>& s) {
    auto pack = [](const std::vector<T>& states, int size, std::vector<P>& packs) {
      packs.resize(static_cast<size_t>(kGroups * size));
      for (int g = 0; g < kGroups; ++g) {
        rbdc_gen::pack_states(states.data() + static_cast<size_t>(g * P::lanes * size), size, size,
                              packs.data() + static_cast<size_t>(g * size));
      }
    };
    pack(s.q, mc::nq, q);
    pack(s.v, mc::nv, v);
    pack(s.a, mc::nv, a);
    pack(s.tau, mc::n_joints, tau);
    pack(s.f, 3 * mc::n_feet, f);
  }
  const P* at(const std::vector<P>& x, int size, int state) const {
    return x.data() + static_cast<size_t>((state & (kGroups - 1)) * size);
  }
};

template <class T>
void add_batch_cases(const LoadedRobot& loaded, const std::string& kind) {
  const std::string implementation = kind + "_x" + std::to_string(rbdc_gen::Batch<T>::lanes);
  if (loaded.model.nq != mc::nq || loaded.model.nv != mc::nv)
    throw std::runtime_error("generated/mini_cheetah does not match robots/mini_cheetah.urdf (run tools/regenerate)");
  using Context = BatchContext<T>;
  auto ctx = std::make_shared<Context>(to_arrays<T>(loaded.states));
  auto add = [&](const char* quantity, CallFn call) {
    add_case(loaded.robot.name, quantity, implementation, ctx, call);
  };
  add("inverse_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    mc::inverse_dynamics(c.at(c.q, mc::nq, k), c.at(c.v, mc::nv, k), c.at(c.a, mc::nv, k), c.out.data());
  });
  add("mass_matrix", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    mc::mass_matrix(c.at(c.q, mc::nq, k), c.out.data());
  });
  add("forward_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    mc::forward_dynamics(c.at(c.q, mc::nq, k), c.at(c.v, mc::nv, k), c.at(c.tau, mc::n_joints, k),
                         c.at(c.f, 3 * mc::n_feet, k), c.out.data());
  });
}

void provide_batches() {
  for_each_loaded_robot(
      "generated batches",
      [](const LoadedRobot& loaded) {
        add_batch_cases<double>(loaded, "generated_double");
        add_batch_cases<float>(loaded, "generated_float");
      },
      "mini_cheetah");
}

const bool registered = register_provider(provide_batches);

}  // namespace
}  // namespace rbdc_bench
