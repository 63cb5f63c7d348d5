// dual_ad (derivative_cases.hpp): the generated PRIMAL code on forward-mode dual numbers. The
// directions (q tangents, v for ∂τ; q tangents, v, τ, f for ∂a) go through in chunks of kChunk per
// primal call, as chunked forward-mode AD tools do: Dual<kChunk> keeps each operation a short vector
// loop, and one instantiation per primal function keeps this translation unit quick to compile
// (Dual<60> of the forward dynamics alone took over 10 CPU minutes at -O3).
#include <memory>
#include <vector>

#include "derivative_cases.hpp"
#include "rbdc/manifold.hpp"
#include "rbdc_test/dual.hpp"
#include "registry.hpp"

namespace rbdc_bench::derivatives {
namespace {

constexpr int kChunk = 12;
using D = rbdc_test::Dual<kChunk>;
constexpr int kIdDirections = 2 * nv;                    // q tangents, v
constexpr int kFdDirections = 2 * nv + nj + 3 * nf;      // q tangents, v, τ, f
static_assert(kIdDirections % kChunk == 0 && kFdDirections % kChunk == 0, "whole chunks");

struct DualContext {
  explicit DualContext(const LoadedRobot& loaded) : model(loaded.model), states(loaded.states) {}
  rbdc::Model model;
  std::vector<State> states;
  rbdc::MatrixX T = rbdc::MatrixX::Zero(nq, nv);  ///< ∂(q ⊕ δ)/∂δ: q tangent of each direction
  std::vector<D> q = std::vector<D>(nq), v = std::vector<D>(nv), a = std::vector<D>(nv),
                 tau = std::vector<D>(nj), f = std::vector<D>(3 * nf), out = std::vector<D>(nv);
  Outputs<double> result;
};

/// Inputs with the unit tangents of the stacked directions [first, first + kChunk): direction d is
/// the configuration tangent d (d < nv), then v, τ and f entry by entry.
void seed_chunk(DualContext& c, const State& s, int first) {
  auto tangent = [first](int direction, D& x) {
    if (direction >= first && direction < first + kChunk) x.d[direction - first] = 1.0;
  };
  for (int i = 0; i < nq; ++i) {
    c.q[i] = D(s.q[i]);
    for (int k = 0; k < kChunk && first + k < nv; ++k) c.q[i].d[k] = c.T(i, first + k);
  }
  for (int i = 0; i < nv; ++i) {
    c.v[i] = D(s.v[i]);
    tangent(nv + i, c.v[i]);
    c.a[i] = D(s.a[i]);
  }
  for (int i = 0; i < nj; ++i) {
    c.tau[i] = D(s.tau[i]);
    tangent(2 * nv + i, c.tau[i]);
  }
  for (int i = 0; i < 3 * nf; ++i) {
    c.f[i] = D(s.f.data()[i]);
    tangent(2 * nv + nj + i, c.f[i]);
  }
}

/// Column `first + k` of the stacked Jacobian [∂/∂q ∂/∂v ∂/∂τ ∂/∂f] (nv rows each) from c.out.
void store_chunk(DualContext& c, int first) {
  double* blocks[] = {c.result.dq.data(), c.result.dv.data(), c.result.dtau.data(), c.result.df.data()};
  const int starts[] = {0, nv, 2 * nv, 2 * nv + nj};
  for (int k = 0; k < kChunk; ++k) {
    const int direction = first + k;
    int block = 3;
    while (direction < starts[block]) --block;
    double* column = blocks[block] + (direction - starts[block]) * nv;
    for (int r = 0; r < nv; ++r) column[r] = c.out[r].d[k];
  }
}

}  // namespace

void add_dual(const LoadedRobot& loaded) {
  auto ctx = std::make_shared<DualContext>(loaded);
  add_case(loaded.robot.name, kId, "dual_ad", ctx, [](void* p, int k) {
    DualContext& c = *static_cast<DualContext*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    rbdc::tangent_map(c.model, s.q, c.T);
    for (int first = 0; first < kIdDirections; first += kChunk) {
      seed_chunk(c, s, first);
      mc::inverse_dynamics(c.q.data(), c.v.data(), c.a.data(), c.out.data());
      store_chunk(c, first);
    }
  });
  add_case(loaded.robot.name, kFd, "dual_ad", ctx, [](void* p, int k) {
    DualContext& c = *static_cast<DualContext*>(p);
    const State& s = c.states[static_cast<size_t>(k)];
    rbdc::tangent_map(c.model, s.q, c.T);
    for (int first = 0; first < kFdDirections; first += kChunk) {
      seed_chunk(c, s, first);
      mc::forward_dynamics(c.q.data(), c.v.data(), c.tau.data(), c.f.data(), c.out.data());
      store_chunk(c, first);
    }
  });
}

}  // namespace rbdc_bench::derivatives
