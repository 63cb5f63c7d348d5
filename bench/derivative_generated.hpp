// The generated derivative code on a scalar T (derivative_cases.hpp): one translation unit per
// scalar, derivative_double.cpp and derivative_float.cpp, so the two compile in parallel.
#pragma once

#include <memory>
#include <string>

#include "derivative_cases.hpp"
#include "registry.hpp"

namespace rbdc_bench::derivatives {

template <class T>
struct GeneratedContext {
  StateArrays<T> s;
  Outputs<T> out;
};

template <class T>
void add_generated(const LoadedRobot& loaded, const std::string& implementation) {
  using Context = GeneratedContext<T>;
  auto ctx = std::make_shared<Context>();
  ctx->s = to_arrays<T>(loaded.states);
  add_case(loaded.robot.name, kId, implementation, ctx, [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    mc::inverse_dynamics_derivatives(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.out.dq.data(),
                                     c.out.dv.data());
  });
  add_case(loaded.robot.name, kFd, implementation, ctx, [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    mc::forward_dynamics_derivatives(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k),
                                     c.out.dq.data(), c.out.dv.data(), c.out.dtau.data(),
                                     c.out.df.data());
  });
}

}  // namespace rbdc_bench::derivatives
