// Derivatives of the dynamics (issue 12) on the Mini Cheetah, quantities
// "inverse_dynamics_derivatives" (∂τ/∂q, ∂τ/∂v) and "forward_dynamics_derivatives" (∂a/∂q, ∂a/∂v,
// ∂a/∂τ, ∂a/∂f), five ways:
//   generated_double, generated_float  the generated derivative code (scene `derivatives`)
//   generated_double_x8                the same on Batch<double>: time per call of 8 states
//   runtime                            the runtime's analytic derivatives (rbdc/derivatives.hpp)
//   dual_ad                            the generated PRIMAL code on forward-mode duals, all
//                                      directions in one call (tests/generator/include/rbdc_test/dual.hpp)
//   finite_differences                 central differences of the generated primal code in double,
//                                      q stepped on the manifold with rbdc::integrate
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mini_cheetah/derivatives.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc/manifold.hpp"
#include "rbdc_gen/batch.hpp"
#include "rbdc_test/dual.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

namespace mc = rbdc_gen::mini_cheetah::derivatives;
constexpr int nq = mc::nq, nv = mc::nv, nj = mc::n_joints, nf = mc::n_feet;
constexpr const char* kId = "inverse_dynamics_derivatives";
constexpr const char* kFd = "forward_dynamics_derivatives";

/// Outputs large enough for both quantities.
template <class T>
struct Outputs {
  std::vector<T> dq = std::vector<T>(nv * nv), dv = std::vector<T>(nv * nv),
                 dtau = std::vector<T>(nv * nj), df = std::vector<T>(nv * 3 * nf);
};

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

/// Batch<double>: states packed 8 at a time, as in batch_cases.cpp.
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

void add_batch(const LoadedRobot& loaded) {
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

/// Dual numbers: (q tangents, v) for inverse dynamics; (q tangents, v, τ, f) for forward dynamics.
constexpr int kIdDirections = 2 * nv;
constexpr int kFdDirections = 2 * nv + nj + 3 * nf;
using rbdc_test::Dual;

struct DualContext {
  StateArrays<double> s;
  std::vector<Dual<kIdDirections>> id_q = std::vector<Dual<kIdDirections>>(nq),
                                   id_v = std::vector<Dual<kIdDirections>>(nv),
                                   id_a = std::vector<Dual<kIdDirections>>(nv),
                                   id_tau = std::vector<Dual<kIdDirections>>(nv);
  std::vector<Dual<kFdDirections>> fd_q = std::vector<Dual<kFdDirections>>(nq),
                                   fd_v = std::vector<Dual<kFdDirections>>(nv),
                                   fd_tau = std::vector<Dual<kFdDirections>>(nj),
                                   fd_f = std::vector<Dual<kFdDirections>>(3 * nf),
                                   fd_a = std::vector<Dual<kFdDirections>>(nv);
};

/// Values from x, unit tangents from direction `first` on (the seeding is part of the timed call).
template <int N>
void seed(const double* x, int size, int first, Dual<N>* out) {
  for (int i = 0; i < size; ++i) out[i] = Dual<N>::variable(x[i], first + i);
}

void add_dual(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<DualContext>();
  ctx->s = to_arrays<double>(loaded.states);
  add_case(loaded.robot.name, kId, "dual_ad", ctx, [](void* p, int k) {
    DualContext& c = *static_cast<DualContext*>(p);
    rbdc_test::seed_configuration<kIdDirections>(c.s.q_at(k), nq, nv, 0, c.id_q.data());
    seed(c.s.v_at(k), nv, nv, c.id_v.data());
    for (int i = 0; i < nv; ++i) c.id_a[static_cast<size_t>(i)] = c.s.a_at(k)[i];
    mc::inverse_dynamics(c.id_q.data(), c.id_v.data(), c.id_a.data(), c.id_tau.data());
  });
  add_case(loaded.robot.name, kFd, "dual_ad", ctx, [](void* p, int k) {
    DualContext& c = *static_cast<DualContext*>(p);
    rbdc_test::seed_configuration<kFdDirections>(c.s.q_at(k), nq, nv, 0, c.fd_q.data());
    seed(c.s.v_at(k), nv, nv, c.fd_v.data());
    seed(c.s.tau_at(k), nj, 2 * nv, c.fd_tau.data());
    seed(c.s.f_at(k), 3 * nf, 2 * nv + nj, c.fd_f.data());
    mc::forward_dynamics(c.fd_q.data(), c.fd_v.data(), c.fd_tau.data(), c.fd_f.data(), c.fd_a.data());
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
        add_generated<double>(loaded, "generated_double");
        add_generated<float>(loaded, "generated_float");
        add_batch(loaded);
        add_runtime(loaded);
        add_dual(loaded);
        add_finite_differences(loaded);
      },
      "mini_cheetah");
}

const bool registered = register_provider(provide_derivatives);

}  // namespace
}  // namespace rbdc_bench
