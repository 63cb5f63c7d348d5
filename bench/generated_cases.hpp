// Generated code (docs/generated_api.md) in double and float on one robot, through its adapter
// struct (rbdc_bench/generated/<robot>.hpp). The raw-pointer overloads read the state set directly.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {

template <class Api, class T>
struct GeneratedContext {
  StateArrays<T> s;
  T ground_mass;       ///< paper 001 Eq. 58 with this scalar's ε
  std::vector<T> out;  ///< nv × nv, large enough for every result
  std::vector<T> p, JbarT, b;
};

template <class Api, class T>
void add_generated_cases(const LoadedRobot& loaded, const std::string& implementation) {
  const rbdc::Model& model = loaded.model;
  if (model.nq != Api::nq || model.nv != Api::nv ||
      static_cast<int>(model.feet.size()) != Api::n_feet)
    throw std::runtime_error("the generated code does not match robots/" + loaded.robot.name +
                             ".urdf (run tools/regenerate)");
  using Context = GeneratedContext<Api, T>;
  auto ctx = std::make_shared<Context>();
  ctx->s = to_arrays<T>(loaded.states);
  ctx->ground_mass = static_cast<T>(smallest_body_mass(model) /
                                    std::sqrt(static_cast<double>(std::numeric_limits<T>::epsilon())));
  ctx->out.assign(static_cast<size_t>(Api::nv * std::max(Api::nv, 3 * Api::n_feet)), T(0));
  ctx->p.assign(static_cast<size_t>(3 * Api::n_feet), T(0));
  ctx->JbarT.assign(static_cast<size_t>(6 * Api::n_joints), T(0));
  ctx->b.assign(6, T(0));
  auto add = [&](const char* quantity, CallFn call) {
    add_case(loaded.robot.name, quantity, implementation, ctx, call);
  };
  add("kinematics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::feet_velocities(c.s.q_at(k), c.s.v_at(k), c.out.data());
  });
  add("feet_positions_jacobian", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::feet_positions(c.s.q_at(k), c.p.data());
    Api::feet_jacobian(c.s.q_at(k), c.out.data());
  });
  add("quadratic_velocity_terms", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::quadratic_velocity_terms(c.s.q_at(k), c.s.v_at(k), c.out.data());
  });
  add("gravity_terms", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::gravity_terms(c.s.q_at(k), c.out.data());
  });
  add("bias", [](void* p, int k) {  // c + g, the dedicated one-pass function
    Context& c = *static_cast<Context*>(p);
    Api::bias(c.s.q_at(k), c.s.v_at(k), c.out.data());
  });
  add("inverse_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::inverse_dynamics(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.out.data());
  });
  add("mass_matrix", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::mass_matrix(c.s.q_at(k), c.out.data());
  });
  add("forward_dynamics", [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    Api::forward_dynamics(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k), c.out.data());
  });
  if constexpr (Api::has_osc) {
    add("osc_open_chain", [](void* p, int k) {
      Context& c = *static_cast<Context*>(p);
      Api::osc_open_chain(c.s.q_at(k), c.s.v_at(k), c.s.f_at(k), c.out.data(), c.JbarT.data(),
                          c.b.data());
    });
    add("osc_closed_chain", [](void* p, int k) {
      Context& c = *static_cast<Context*>(p);
      Api::osc_closed_chain(c.s.q_at(k), c.s.v_at(k), &c.ground_mass, c.out.data(), c.JbarT.data(),
                            c.b.data());
    });
  }
}

/// The provider body for one generated robot: double and float cases.
template <class Api>
void provide_generated() {
  for_each_loaded_robot(
      "generated",
      [](const LoadedRobot& loaded) {
        add_generated_cases<Api, double>(loaded, "generated_double");
        add_generated_cases<Api, float>(loaded, "generated_float");
      },
      Api::name);
}

}  // namespace rbdc_bench
