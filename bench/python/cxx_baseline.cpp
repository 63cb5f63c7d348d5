// The C++ side of bench/python/measure.py: the same generated Mini Cheetah `full` code the Python
// module calls (the cache entry's headers), timed without Python. Prints, per function, the
// single-state time (ns per call, states cycled) and the batch time of N states stored one after
// another (ns per state, Batch<double> packs: pack, call, unpack, as the bindings do).
// Usage: cxx_baseline N
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#include "mini_cheetah/full.hpp"
#include "rbdc_gen/batch.hpp"

namespace mc = rbdc_gen::mini_cheetah::full;
using P = rbdc_gen::Batch<double>;

/// CPU seconds of this process (not wall time: the figures stay meaningful on a shared machine).
template <class F>
double seconds(F&& f) {
  const std::clock_t start = std::clock();
  f();
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> q(n * mc::nq), v(n * mc::nv), a(n * mc::nv), tau(n * mc::nv), M(n * mc::nv * mc::nv);
  for (double& x : q) x = u(rng);
  for (double& x : v) x = u(rng);
  for (double& x : a) x = u(rng);
  volatile double sink = 0;
  // Single states, cycled through the first 1024.
  const long calls = 2000000;
  const double id_single = seconds([&] {
    for (long k = 0; k < calls; ++k) {
      const long s = k & 1023;
      mc::inverse_dynamics(&q[s * mc::nq], &v[s * mc::nv], &a[s * mc::nv], &tau[s * mc::nv]);
    }
  });
  const double m_single = seconds([&] {
    for (long k = 0; k < calls; ++k) mc::mass_matrix(&q[(k & 1023) * mc::nq], &M[(k & 1023) * mc::nv * mc::nv]);
  });
  // Batches: W states packed, computed, unpacked.
  const double id_batch = seconds([&] {
    P pq[mc::nq], pv[mc::nv], pa[mc::nv], ptau[mc::nv];
    for (long s = 0; s + P::lanes <= n; s += P::lanes) {
      rbdc_gen::pack_states(&q[s * mc::nq], mc::nq, mc::nq, pq);
      rbdc_gen::pack_states(&v[s * mc::nv], mc::nv, mc::nv, pv);
      rbdc_gen::pack_states(&a[s * mc::nv], mc::nv, mc::nv, pa);
      mc::inverse_dynamics(pq, pv, pa, ptau);
      rbdc_gen::unpack_states(ptau, mc::nv, &tau[s * mc::nv], mc::nv);
    }
  });
  const double m_batch = seconds([&] {
    P pq[mc::nq], pM[mc::nv * mc::nv];
    for (long s = 0; s + P::lanes <= n; s += P::lanes) {
      rbdc_gen::pack_states(&q[s * mc::nq], mc::nq, mc::nq, pq);
      mc::mass_matrix(pq, pM);
      rbdc_gen::unpack_states(pM, mc::nv * mc::nv, &M[s * mc::nv * mc::nv], mc::nv * mc::nv);
    }
  });
  sink = tau[0] + M[0];
  std::printf("{\"inverse_dynamics\": {\"single_ns\": %.1f, \"batch_ns_per_state\": %.1f},\n"
              " \"mass_matrix\": {\"single_ns\": %.1f, \"batch_ns_per_state\": %.1f}}\n",
              1e9 * id_single / calls, 1e9 * id_batch / n, 1e9 * m_single / calls, 1e9 * m_batch / n);
  return sink == 12345.678 ? 1 : 0;
}
