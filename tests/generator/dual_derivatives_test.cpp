// The third opinion on the generated derivatives (issue 12): the generated PRIMAL functions
// instantiated on a forward-mode dual number (tests/generator/include/rbdc_test/dual.hpp), seeded
// along the manifold tangents of docs/conventions.md, reproduce every generated derivative to
// 1e-12 relative, for a floating base (Mini Cheetah, humanoid) and a fixed base (arm).
#include <gtest/gtest.h>

#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "arm7/derivatives.hpp"
#include "humanoid32/derivatives.hpp"
#include "mini_cheetah/derivatives.hpp"
#include "rbdc_test/dual.hpp"

namespace {

using rbdc_test::Dual;
constexpr double kTolerance = 1e-12;
constexpr int kStates = 10;

/// A random state: unit quaternion for a floating base, joints in [-π, π], v, τ, f as in verify.
struct State {
  std::vector<double> q, v, a, tau, f;
};

State random_state(int nq, int nv, int n_joints, int n_feet, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  State s{std::vector<double>(nq), std::vector<double>(nv), std::vector<double>(nv),
          std::vector<double>(n_joints), std::vector<double>(3 * n_feet)};
  for (double& x : s.q) x = M_PI * unit(rng);
  if (nq != nv) {
    double norm = 0;
    for (int k = 3; k < 7; ++k) norm += s.q[k] * s.q[k];
    for (int k = 3; k < 7; ++k) s.q[k] /= std::sqrt(norm);
  }
  for (double& x : s.v) x = 2 * unit(rng);
  for (double& x : s.a) x = 5 * unit(rng);
  for (double& x : s.tau) x = 10 * unit(rng);
  for (double& x : s.f) x = 50 * unit(rng);
  return s;
}

template <int N>
std::vector<Dual<N>> constant(const std::vector<double>& x) {
  return std::vector<Dual<N>>(x.begin(), x.end());
}

/// Plain partials: directions first … first + size − 1 along x's entries.
template <int N>
std::vector<Dual<N>> variable(const std::vector<double>& x, int first) {
  std::vector<Dual<N>> out = constant<N>(x);
  for (size_t k = 0; k < x.size(); ++k) out[k].d[first + static_cast<int>(k)] = 1.0;
  return out;
}

template <int N>
std::vector<Dual<N>> configuration(const State& s, int nv, int first) {
  std::vector<Dual<N>> q(s.q.size());
  rbdc_test::seed_configuration<N>(s.q.data(), static_cast<int>(s.q.size()), nv, first, q.data());
  return q;
}

/// Largest |generated − dual| over the block (rows × cols, column-major) relative to the largest
/// dual entry (floored at 1), where column c is tangent direction first + c.
template <int N>
double relative_error(const std::vector<double>& generated, const std::vector<Dual<N>>& y, int rows,
                      int cols, int first) {
  double difference = 0, scale = 1;
  for (int c = 0; c < cols; ++c) {
    for (int r = 0; r < rows; ++r) {
      const double want = y[static_cast<size_t>(r)].d[first + c];
      difference = std::max(difference, std::abs(generated[static_cast<size_t>(r + rows * c)] - want));
      scale = std::max(scale, std::abs(want));
    }
  }
  return difference / scale;
}

/// Every derivative quantity of one generated `derivatives` scene against duals of its primal code.
#define RBDC_DUAL_CHECKS(NS)                                                                            \
  namespace gen = NS;                                                                                   \
  constexpr int nq = gen::nq, nv = gen::nv, nj = gen::n_joints, nf = gen::n_feet;                        \
  std::mt19937_64 rng(7);                                                                               \
  for (int n = 0; n < kStates; ++n) {                                                                   \
    const State s = random_state(nq, nv, nj, nf, rng);                                                  \
    SCOPED_TRACE("state " + std::to_string(n));                                                         \
    {                                                                                                   \
      constexpr int N = 2 * nv; /* inverse dynamics, bias: (q tangents, v) */                           \
      std::vector<double> dq(nv * nv), dv(nv * nv);                                                     \
      std::vector<Dual<N>> tau(nv);                                                                     \
      const auto q = configuration<N>(s, nv, 0);                                                        \
      const auto v = variable<N>(s.v, nv);                                                              \
      gen::inverse_dynamics_derivatives<double>(s.q.data(), s.v.data(), s.a.data(), dq.data(), dv.data()); \
      gen::inverse_dynamics<Dual<N>>(q.data(), v.data(), constant<N>(s.a).data(), tau.data());         \
      EXPECT_LE(relative_error(dq, tau, nv, nv, 0), kTolerance) << "dtau_dq";                          \
      EXPECT_LE(relative_error(dv, tau, nv, nv, nv), kTolerance) << "dtau_dv";                         \
      gen::bias_derivatives<double>(s.q.data(), s.v.data(), dq.data(), dv.data());                     \
      gen::inverse_dynamics<Dual<N>>(q.data(), v.data(), constant<N>(std::vector<double>(nv)).data(),   \
                                     tau.data());                                                       \
      EXPECT_LE(relative_error(dq, tau, nv, nv, 0), kTolerance) << "dbias_dq";                         \
      EXPECT_LE(relative_error(dv, tau, nv, nv, nv), kTolerance) << "dbias_dv";                        \
    }                                                                                                   \
    {                                                                                                   \
      constexpr int N = nv; /* q tangents only */                                                       \
      std::vector<double> dg(nv * nv), dpdot(3 * nf * nv), dtau_e(nv * nv);                             \
      std::vector<Dual<N>> g(nv), pdot(3 * nf), tau_e(nv);                                              \
      const auto q = configuration<N>(s, nv, 0);                                                        \
      gen::gravity_derivatives<double>(s.q.data(), dg.data());                                          \
      gen::gravity_terms<Dual<N>>(q.data(), g.data());                                                  \
      EXPECT_LE(relative_error(dg, g, nv, nv, 0), kTolerance) << "dg_dq";                              \
      gen::feet_velocity_derivatives<double>(s.q.data(), s.v.data(), dpdot.data());                     \
      gen::feet_velocities<Dual<N>>(q.data(), constant<N>(s.v).data(), pdot.data());                    \
      EXPECT_LE(relative_error(dpdot, pdot, 3 * nf, nv, 0), kTolerance) << "dpdot_dq";                 \
      gen::feet_force_term_derivatives<double>(s.q.data(), s.f.data(), dtau_e.data());                  \
      gen::feet_force_terms<Dual<N>>(q.data(), constant<N>(s.f).data(), tau_e.data());                  \
      EXPECT_LE(relative_error(dtau_e, tau_e, nv, nv, 0), kTolerance) << "dtau_e_dq";                  \
    }                                                                                                   \
    {                                                                                                   \
      constexpr int N = 2 * nv + nj + 3 * nf; /* (q tangents, v, tau, f) through the factorisation */   \
      std::vector<double> da_dq(nv * nv), da_dv(nv * nv), da_dtau(nv * nj), da_df(nv * 3 * nf);         \
      std::vector<Dual<N>> acceleration(nv);                                                            \
      gen::forward_dynamics_derivatives<double>(s.q.data(), s.v.data(), s.tau.data(), s.f.data(),       \
                                                da_dq.data(), da_dv.data(), da_dtau.data(), da_df.data()); \
      gen::forward_dynamics<Dual<N>>(configuration<N>(s, nv, 0).data(), variable<N>(s.v, nv).data(),    \
                                     variable<N>(s.tau, 2 * nv).data(),                                 \
                                     variable<N>(s.f, 2 * nv + nj).data(), acceleration.data());        \
      EXPECT_LE(relative_error(da_dq, acceleration, nv, nv, 0), kTolerance) << "da_dq";                \
      EXPECT_LE(relative_error(da_dv, acceleration, nv, nv, nv), kTolerance) << "da_dv";               \
      EXPECT_LE(relative_error(da_dtau, acceleration, nv, nj, 2 * nv), kTolerance) << "da_dtau";       \
      EXPECT_LE(relative_error(da_df, acceleration, nv, 3 * nf, 2 * nv + nj), kTolerance) << "da_df";  \
    }                                                                                                   \
  }

/// Runs `body` on a thread with a 1 GiB stack: at -O0 every temporary of a generated function has its
/// own stack slot, and the humanoid's forward dynamics on Dual<132> holds about 14 000 of them.
void run_on_large_stack(std::function<void()> body) {
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstacksize(&attributes, size_t{1} << 30);
  pthread_t thread;
  auto run = [](void* p) -> void* {
    (*static_cast<std::function<void()>*>(p))();
    return nullptr;
  };
  ASSERT_EQ(pthread_create(&thread, &attributes, run, &body), 0);
  pthread_join(thread, nullptr);
  pthread_attr_destroy(&attributes);
}

TEST(DualDerivatives, MiniCheetahFloatingBase) {
  run_on_large_stack([] { RBDC_DUAL_CHECKS(rbdc_gen::mini_cheetah::derivatives) });
}

TEST(DualDerivatives, Arm7FixedBase) {
  run_on_large_stack([] { RBDC_DUAL_CHECKS(rbdc_gen::arm7::derivatives) });
}

TEST(DualDerivatives, Humanoid32FloatingBase) {
  run_on_large_stack([] { RBDC_DUAL_CHECKS(rbdc_gen::humanoid32::derivatives) });
}

/// The dual seeding itself: a dual step along each tangent equals a finite step of q ⊕ δ to first
/// order, checked on the quaternion's unit norm (its tangent is orthogonal to q).
TEST(DualDerivatives, QuaternionTangentsAreOrthogonalToTheQuaternion) {
  const std::vector<double> q = {0.1, 0.2, 0.3, 0.5, -0.5, 0.5, 0.5, 0.4};
  std::vector<Dual<7>> seeded(q.size());
  rbdc_test::seed_configuration<7>(q.data(), 8, 7, 0, seeded.data());
  for (int k = 0; k < 3; ++k) {
    double dot = 0;
    for (int c = 3; c < 7; ++c) dot += q[static_cast<size_t>(c)] * seeded[static_cast<size_t>(c)].d[k];
    EXPECT_NEAR(dot, 0.0, 1e-15);
  }
  EXPECT_EQ(seeded[7].d[6], 1.0);
}

}  // namespace
