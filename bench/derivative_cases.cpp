// The reference implementations of the derivatives and the primal calls they are quoted against
// (derivative_cases.hpp), and the provider that registers every derivative case.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "derivative_cases.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc/manifold.hpp"
#include "registry.hpp"

namespace rbdc_bench::derivatives {
namespace {

/// The primal functions the derivatives are quoted against, from the same generated scene.
struct PrimalContext {
  StateArrays<double> s;
  std::vector<double> out = std::vector<double>(nv);
};

void add_primal(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<PrimalContext>();
  ctx->s = to_arrays<double>(loaded.states);
  add_case(loaded.robot.name, "inverse_dynamics", "generated_double", ctx, [](void* p, int k) {
    PrimalContext& c = *static_cast<PrimalContext*>(p);
    mc::inverse_dynamics(c.s.q_at(k), c.s.v_at(k), c.s.a_at(k), c.out.data());
  });
  add_case(loaded.robot.name, "forward_dynamics", "generated_double", ctx, [](void* p, int k) {
    PrimalContext& c = *static_cast<PrimalContext*>(p);
    mc::forward_dynamics(c.s.q_at(k), c.s.v_at(k), c.s.tau_at(k), c.s.f_at(k), c.out.data());
  });
}

struct RuntimeContext {
  explicit RuntimeContext(const LoadedRobot& loaded)
      : model(loaded.model), data(model), derivatives(model), states(loaded.states) {}
  rbdc::Model model;
  rbdc::Data data;
  rbdc::DerivativeData derivatives;
  std::vector<State> states;
};

void add_runtime(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<RuntimeContext>(loaded);
  add_case(loaded.robot.name, kId, "runtime", ctx, [](void* p, int k) {
    RuntimeContext& c = *static_cast<RuntimeContext*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    rbdc::inverse_dynamics_derivatives(c.model, c.data, c.derivatives, s.q, s.v, s.a);
  });
  add_case(loaded.robot.name, kFd, "runtime", ctx, [](void* p, int k) {
    RuntimeContext& c = *static_cast<RuntimeContext*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    rbdc::forward_dynamics_derivatives(c.model, c.data, c.derivatives, s.q, s.v, s.tau, s.f);
  });
}

/// Central differences with step h: 2 primal calls per direction, q stepped with rbdc::integrate.
struct FiniteDifferenceContext {
  explicit FiniteDifferenceContext(const LoadedRobot& loaded)
      : model(loaded.model), states(loaded.states) {}
  rbdc::Model model;
  std::vector<State> states;
  rbdc::VectorX delta = rbdc::VectorX::Zero(nv), q_plus = rbdc::VectorX::Zero(nq),
                q_minus = rbdc::VectorX::Zero(nq), x_plus, x_minus;
  Outputs<double> out;
  std::vector<double> plus = std::vector<double>(nv), minus = std::vector<double>(nv);
};
constexpr double kStep = 1e-6;

/// Column k of ∂primal/∂q: primal(q ⊕ ±h e_k) through `call(q, result)`.
template <class Call>
void q_column(FiniteDifferenceContext& c, const State& s, int k, double* column, Call call) {
  c.delta.setZero();
  c.delta[k] = kStep;
  rbdc::integrate(c.model, s.q, c.delta, c.q_plus);
  c.delta[k] = -kStep;
  rbdc::integrate(c.model, s.q, c.delta, c.q_minus);
  call(c.q_plus.data(), c.plus.data());
  call(c.q_minus.data(), c.minus.data());
  for (int r = 0; r < nv; ++r) column[r] = (c.plus[r] - c.minus[r]) / (2 * kStep);
}

/// Column k of ∂primal/∂x for a plain input x (a copy in `x` is stepped in place).
template <class Call>
void plain_column(FiniteDifferenceContext& c, rbdc::VectorX& x, int k, double* column, Call call) {
  const double keep = x[k];
  x[k] = keep + kStep;
  call(x.data(), c.plus.data());
  x[k] = keep - kStep;
  call(x.data(), c.minus.data());
  x[k] = keep;
  for (int r = 0; r < nv; ++r) column[r] = (c.plus[r] - c.minus[r]) / (2 * kStep);
}

void add_finite_differences(const LoadedRobot& loaded) {
  using Context = FiniteDifferenceContext;
  auto ctx = std::make_shared<Context>(loaded);
  add_case(loaded.robot.name, kId, "finite_differences", ctx, [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    c.x_plus = s.v;
    for (int j = 0; j < nv; ++j) {
      q_column(c, s, j, c.out.dq.data() + j * nv, [&](const double* q, double* tau) {
        mc::inverse_dynamics(q, s.v.data(), s.a.data(), tau);
      });
      plain_column(c, c.x_plus, j, c.out.dv.data() + j * nv, [&](const double* v, double* tau) {
        mc::inverse_dynamics(s.q.data(), v, s.a.data(), tau);
      });
    }
  });
  add_case(loaded.robot.name, kFd, "finite_differences", ctx, [](void* p, int k) {
    Context& c = *static_cast<Context*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    const double* f = s.f.data();
    c.x_plus = s.v;
    for (int j = 0; j < nv; ++j) {
      q_column(c, s, j, c.out.dq.data() + j * nv, [&](const double* q, double* a) {
        mc::forward_dynamics(q, s.v.data(), s.tau.data(), f, a);
      });
      plain_column(c, c.x_plus, j, c.out.dv.data() + j * nv, [&](const double* v, double* a) {
        mc::forward_dynamics(s.q.data(), v, s.tau.data(), f, a);
      });
    }
    c.x_plus = s.tau;
    for (int j = 0; j < nj; ++j) {
      plain_column(c, c.x_plus, j, c.out.dtau.data() + j * nv, [&](const double* tau, double* a) {
        mc::forward_dynamics(s.q.data(), s.v.data(), tau, f, a);
      });
    }
    c.x_plus = Eigen::Map<const rbdc::VectorX>(f, 3 * nf);
    for (int j = 0; j < 3 * nf; ++j) {
      plain_column(c, c.x_plus, j, c.out.df.data() + j * nv, [&](const double* force, double* a) {
        mc::forward_dynamics(s.q.data(), s.v.data(), s.tau.data(), force, a);
      });
    }
  });
}

void provide_derivatives() {
  for_each_loaded_robot(
      "derivatives",
      [](const LoadedRobot& loaded) {
        if (loaded.model.nq != nq || loaded.model.nv != nv ||
            static_cast<int>(loaded.model.feet.size()) != nf)
          throw std::runtime_error("generated/mini_cheetah/derivatives does not match the robot "
                                   "(run tools/regenerate)");
        add_primal(loaded);
        add_generated_double(loaded);
        add_generated_float(loaded);
        add_generated_batch(loaded);
        add_runtime(loaded);
        add_dual(loaded);
        add_finite_differences(loaded);
      },
      "mini_cheetah");
}

const bool registered = register_provider(provide_derivatives);

}  // namespace
}  // namespace rbdc_bench::derivatives
