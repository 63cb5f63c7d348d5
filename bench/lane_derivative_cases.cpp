// The Mini Cheetah's derivatives with the legs in SIMD lanes (scene limb_lanes) next to the scalar
// ones (scene derivatives), one state per call, so that bench/report --lanes-only times both in one
// run. Implementations "generated_double_lanes" and "generated_double"; quantities named as in
// rbdc-bench-derivatives. Built only with RBDC_BENCH_DERIVATIVES (minutes of -O3 compile).
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mini_cheetah/derivatives.hpp"
#include "mini_cheetah/limb_lanes.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

namespace md = rbdc_gen::mini_cheetah::derivatives;
namespace ml = rbdc_gen::mini_cheetah::limb_lanes;

struct DerivativeContext {
  StateArrays<double> s;
  std::vector<double> d1 = std::vector<double>(md::nv * md::nv), d2 = d1, d3 = d1, d4 = d1;
};

template <bool kLanes>
void add_derivative_cases(const LoadedRobot& loaded, const std::string& implementation) {
  if (loaded.model.nq != md::nq || loaded.model.nv != md::nv)
    throw std::runtime_error("generated/mini_cheetah does not match robots/mini_cheetah.urdf (run tools/regenerate)");
  auto ctx = std::make_shared<DerivativeContext>();
  ctx->s = to_arrays<double>(loaded.states);
  add_case(loaded.robot.name, "inverse_dynamics_derivatives", implementation, ctx, [](void* p, int k) {
    DerivativeContext& c = *static_cast<DerivativeContext*>(p);
    if constexpr (kLanes)
      ml::inverse_dynamics_derivatives_lanes(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.d1.data(), c.d2.data());
    else
      md::inverse_dynamics_derivatives(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.d1.data(), c.d2.data());
  });
  add_case(loaded.robot.name, "forward_dynamics_derivatives", implementation, ctx, [](void* p, int k) {
    DerivativeContext& c = *static_cast<DerivativeContext*>(p);
    if constexpr (kLanes)
      ml::forward_dynamics_derivatives_lanes(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k), c.d1.data(),
                                             c.d2.data(), c.d3.data(), c.d4.data());
    else
      md::forward_dynamics_derivatives(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k), c.d1.data(),
                                       c.d2.data(), c.d3.data(), c.d4.data());
  });
}

void provide_lane_derivatives() {
  for_each_loaded_robot(
      "generated derivatives, lanes and scalar",
      [](const LoadedRobot& loaded) {
        add_derivative_cases<true>(loaded, "generated_double_lanes");
        add_derivative_cases<false>(loaded, "generated_double");
      },
      "mini_cheetah");
}

const bool registered = register_provider(provide_lane_derivatives);

}  // namespace
}  // namespace rbdc_bench
