// The runtime (rbdc::runtime, dense reference algorithms) on every benchmark robot.
#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/osc.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

struct RuntimeContext {
  explicit RuntimeContext(const LoadedRobot& loaded)
      : model(loaded.model), data(model), closed_form(model), states(loaded.states),
        zero_a(rbdc::VectorX::Zero(model.nv)), ground_mass(loaded.ground_mass) {
    for (int k = 0; k < static_cast<int>(model.feet.size()); ++k) all_feet.push_back(k);
  }
  rbdc::Model model;
  rbdc::Data data;
  rbdc::OscReferenceData closed_form;
  std::vector<State> states;
  rbdc::VectorX zero_a;
  double ground_mass;
  std::vector<int> all_feet;  ///< every foot in contact, as the generated full scene has it
};

RuntimeContext& context(void* p) { return *static_cast<RuntimeContext*>(p); }
const State& state(RuntimeContext& c, int k) { return c.states[static_cast<size_t>(k)]; }

void provide() {
  for_each_loaded_robot("runtime", [](const LoadedRobot& loaded) {
    auto ctx = std::make_shared<RuntimeContext>(loaded);
    auto add = [&](const char* quantity, CallFn call) {
      add_case(loaded.robot.name, quantity, "runtime", ctx, call);
    };
    add("kinematics", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::feet_velocities(c.model, c.data, state(c, k).q, state(c, k).v);
    });
    add("feet_positions_jacobian", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::feet_positions(c.model, c.data, state(c, k).q);
      rbdc::feet_jacobian(c.model, c.data, state(c, k).q);
    });
    add("quadratic_velocity_terms", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::quadratic_velocity_terms(c.model, c.data, state(c, k).q, state(c, k).v);
    });
    add("gravity_terms", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::gravity_terms(c.model, c.data, state(c, k).q);
    });
    add("bias", [](void* p, int k) {  // c + g as one RNEA with a = 0
      RuntimeContext& c = context(p);
      rbdc::inverse_dynamics(c.model, c.data, state(c, k).q, state(c, k).v, c.zero_a);
    });
    add("inverse_dynamics", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::inverse_dynamics(c.model, c.data, state(c, k).q, state(c, k).v, state(c, k).a);
    });
    add("mass_matrix", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::mass_matrix(c.model, c.data, state(c, k).q);
    });
    add("forward_dynamics", [](void* p, int k) {
      RuntimeContext& c = context(p);
      const State& s = state(c, k);
      rbdc::forward_dynamics(c.model, c.data, s.q, s.v, s.tau, s.f);
    });
    // No trunk task on a fixed base; the OSC recursions refuse mimic couplings.
    if (!loaded.model.floating_base || !loaded.model.couplings.empty()) return;
    add("osc_open_chain", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::osc_open_chain(c.model, c.data, state(c, k).q, state(c, k).v, state(c, k).f);
    });
    add("osc_closed_chain", [](void* p, int k) {
      RuntimeContext& c = context(p);
      rbdc::osc_closed_chain(c.model, c.data, state(c, k).q, state(c, k).v, c.all_feet,
                             c.ground_mass);
    });
    add("osc_closed_form", [](void* p, int k) {  // the exact constrained quantities (Eqs. 16-26)
      RuntimeContext& c = context(p);
      rbdc::osc_closed_form_constrained(c.model, c.data, c.closed_form, state(c, k).q, state(c, k).v,
                                        c.all_feet);
    });
  });
}

const bool registered = register_provider(provide);

}  // namespace
}  // namespace rbdc_bench
