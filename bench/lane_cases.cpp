// Generated mini_cheetah code with the legs in SIMD lanes (scene limb_lanes, docs/performance.md):
// one state per call like "generated_double", each leg in one lane of a 4-wide vector.
// Implementations "generated_double_lanes" and "generated_float_lanes", timed in the same run as
// the scalar functions of scene full so that latest.md can quote their ratio; and M's lower triangle
// alone (quantity mass_matrix_lower), in lanes and scalar ("generated_double", "generated_float").
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mini_cheetah/limb_lanes.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

namespace ml = rbdc_gen::mini_cheetah::limb_lanes;

template <class T>
struct LaneContext {
  StateArrays<T> s;
  std::vector<T> out = std::vector<T>(ml::nv * ml::nv);
  std::vector<T> JbarT = std::vector<T>(6 * ml::n_joints), b = std::vector<T>(6);  // OSC
};

template <class T>
void add_lane_cases(const LoadedRobot& loaded, const std::string& implementation) {
  if (loaded.model.nq != ml::nq || loaded.model.nv != ml::nv)
    throw std::runtime_error("generated/mini_cheetah does not match robots/mini_cheetah.urdf (run tools/regenerate)");
  using Context = LaneContext<T>;
  auto ctx = std::make_shared<Context>();
  ctx->s = to_arrays<T>(loaded.states);
  auto add = [&](const char* quantity, CallFn call) {
    add_case(loaded.robot.name, quantity, implementation, ctx, call);
  };
  add("bias", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::bias_lanes(c.s.q_at(k), c.s.v_at(k), c.out.data());
  });
  add("inverse_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::inverse_dynamics_lanes(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.out.data());
  });
  add("mass_matrix", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::mass_matrix_lanes(c.s.q_at(k), c.out.data());
  });
  add("mass_matrix_lower", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::mass_matrix_lower_lanes(c.s.q_at(k), c.out.data());
  });
  add("forward_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::forward_dynamics_lanes(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k), c.out.data());
  });
  add("osc_open_chain", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::osc_open_chain_lanes(c.s.q_at(k), c.s.v_at(k), c.s.f_at(k), c.out.data(), c.JbarT.data(), c.b.data());
  });
}

/// The scalar lower triangle of M, under the scalar implementations' names.
template <class T>
void add_scalar_lower_case(const LoadedRobot& loaded, const std::string& implementation) {
  using Context = LaneContext<T>;
  auto ctx = std::make_shared<Context>();
  ctx->s = to_arrays<T>(loaded.states);
  add_case(loaded.robot.name, "mass_matrix_lower", implementation, ctx, [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    ml::mass_matrix_lower(c.s.q_at(k), c.out.data());
  });
}

void provide_lanes() {
  for_each_loaded_robot(
      "generated lanes",
      [](const LoadedRobot& loaded) {
        add_lane_cases<double>(loaded, "generated_double_lanes");
        add_lane_cases<float>(loaded, "generated_float_lanes");
        add_scalar_lower_case<double>(loaded, "generated_double");
        add_scalar_lower_case<float>(loaded, "generated_float");
      },
      "mini_cheetah");
}

const bool registered = register_provider(provide_lanes);

}  // namespace
}  // namespace rbdc_bench
