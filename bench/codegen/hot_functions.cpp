// bench/codegen/metrics: one out-of-line wrapper per hot generated function of the Mini Cheetah
// (scene "full"; scene "limb_lanes" with RBDC_HOT_HAS_LANES; the derivative functions only when
// asked for, RBDC_HOT_WANTS_<name>: each takes minutes to compile), so that callgrind can count the
// instructions of one call and objdump can show the stack traffic (spills) of one function body.
// Not a benchmark: the rough ns are a side note.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "mini_cheetah/full.hpp"
#ifdef RBDC_HOT_HAS_LANES
#include "mini_cheetah/limb_lanes.hpp"
#endif
#if defined(RBDC_HOT_WANTS_inverse_dynamics_derivatives) || defined(RBDC_HOT_WANTS_forward_dynamics_derivatives)
#include "mini_cheetah/derivatives.hpp"
#endif

namespace g = rbdc_gen::mini_cheetah::full;
#ifdef RBDC_HOT_HAS_LANES
namespace lanes = rbdc_gen::mini_cheetah::limb_lanes;
#endif

extern "C" {
__attribute__((noinline)) void hot_inverse_dynamics(const double* q, const double* v, const double* a,
                                                     double* out) {
  g::inverse_dynamics(q, v, a, out);
}
__attribute__((noinline)) void hot_mass_matrix(const double* q, const double*, const double*, double* out) {
  g::mass_matrix(q, out);
}
__attribute__((noinline)) void hot_forward_dynamics(const double* q, const double* v, const double* a,
                                                     double* out) {
  static const double f[12] = {};
  g::forward_dynamics(q, v, a + 6, f, out);
}
__attribute__((noinline)) void hot_quadratic_velocity_terms(const double* q, const double* v, const double*,
                                                             double* out) {
  g::quadratic_velocity_terms(q, v, out);
}
__attribute__((noinline)) void hot_gravity_terms(const double* q, const double*, const double*, double* out) {
  g::gravity_terms(q, out);
}
#ifdef RBDC_HOT_HAS_STRUCTURED_OUTPUTS  // generated code from before bias and the factor lacks them
__attribute__((noinline)) void hot_bias(const double* q, const double* v, const double*, double* out) {
  g::bias(q, v, out);
}
__attribute__((noinline)) void hot_mass_matrix_factor(const double* q, const double*, const double*,
                                                       double* out) {
  g::mass_matrix_factor(q, out, out + g::nv * g::nv, out + g::nv * (g::nv + 1));
}
#endif
#ifdef RBDC_HOT_HAS_LANES  // the legs in SIMD lanes, scene "limb_lanes" (docs/performance.md)
__attribute__((noinline)) void hot_inverse_dynamics_lanes(const double* q, const double* v, const double* a,
                                                           double* out) {
  lanes::inverse_dynamics_lanes(q, v, a, out);
}
__attribute__((noinline)) void hot_bias_lanes(const double* q, const double* v, const double*, double* out) {
  lanes::bias_lanes(q, v, out);
}
__attribute__((noinline)) void hot_forward_dynamics_lanes(const double* q, const double* v, const double* a,
                                                           double* out) {
  static const double f[12] = {};
  lanes::forward_dynamics_lanes(q, v, a + 6, f, out);
}
__attribute__((noinline)) void hot_mass_matrix_lanes(const double* q, const double*, const double*, double* out) {
  lanes::mass_matrix_lanes(q, out);
}
#endif
#ifdef RBDC_HOT_HAS_LOWER  // M's lower triangle alone, scalar and in lanes (scene limb_lanes)
__attribute__((noinline)) void hot_mass_matrix_lower(const double* q, const double*, const double*, double* out) {
  lanes::mass_matrix_lower(q, out);
}
__attribute__((noinline)) void hot_mass_matrix_lower_lanes(const double* q, const double*, const double*,
                                                            double* out) {
  lanes::mass_matrix_lower_lanes(q, out);
}
#endif
// The derivatives: outputs one after the other in `out`; the foot forces zero.
#ifdef RBDC_HOT_WANTS_inverse_dynamics_derivatives
__attribute__((noinline)) void hot_inverse_dynamics_derivatives(const double* q, const double* v, const double* a,
                                                                 double* out) {
  rbdc_gen::mini_cheetah::derivatives::inverse_dynamics_derivatives(q, v, a, out, out + g::nv * g::nv);
}
#endif
#ifdef RBDC_HOT_WANTS_inverse_dynamics_derivatives_lanes
__attribute__((noinline)) void hot_inverse_dynamics_derivatives_lanes(const double* q, const double* v,
                                                                       const double* a, double* out) {
  lanes::inverse_dynamics_derivatives_lanes(q, v, a, out, out + g::nv * g::nv);
}
#endif
constexpr int at_dv = g::nv * g::nv, at_dtau = 2 * at_dv, at_df = at_dtau + g::nv * g::n_joints;
#ifdef RBDC_HOT_WANTS_forward_dynamics_derivatives
__attribute__((noinline)) void hot_forward_dynamics_derivatives(const double* q, const double* v, const double* a,
                                                                 double* out) {
  static const double f[12] = {};
  rbdc_gen::mini_cheetah::derivatives::forward_dynamics_derivatives(q, v, a + 6, f, out, out + at_dv, out + at_dtau,
                                                                   out + at_df);
}
#endif
#ifdef RBDC_HOT_WANTS_forward_dynamics_derivatives_lanes
__attribute__((noinline)) void hot_forward_dynamics_derivatives_lanes(const double* q, const double* v,
                                                                       const double* a, double* out) {
  static const double f[12] = {};
  lanes::forward_dynamics_derivatives_lanes(q, v, a + 6, f, out, out + at_dv, out + at_dtau, out + at_df);
}
#endif
}

using Function = void (*)(const double*, const double*, const double*, double*);
struct Entry { const char* name; Function function; };
static const Entry entries[] = {
    {"inverse_dynamics", hot_inverse_dynamics}, {"mass_matrix", hot_mass_matrix},
    {"forward_dynamics", hot_forward_dynamics},
    {"quadratic_velocity_terms", hot_quadratic_velocity_terms}, {"gravity_terms", hot_gravity_terms},
#ifdef RBDC_HOT_HAS_STRUCTURED_OUTPUTS
    {"bias", hot_bias}, {"mass_matrix_factor", hot_mass_matrix_factor},
#endif
#ifdef RBDC_HOT_HAS_LANES
    {"inverse_dynamics_lanes", hot_inverse_dynamics_lanes}, {"mass_matrix_lanes", hot_mass_matrix_lanes},
    {"bias_lanes", hot_bias_lanes}, {"forward_dynamics_lanes", hot_forward_dynamics_lanes},
#endif
#ifdef RBDC_HOT_HAS_LOWER
    {"mass_matrix_lower", hot_mass_matrix_lower}, {"mass_matrix_lower_lanes", hot_mass_matrix_lower_lanes},
#endif
#ifdef RBDC_HOT_WANTS_inverse_dynamics_derivatives
    {"inverse_dynamics_derivatives", hot_inverse_dynamics_derivatives},
#endif
#ifdef RBDC_HOT_WANTS_inverse_dynamics_derivatives_lanes
    {"inverse_dynamics_derivatives_lanes", hot_inverse_dynamics_derivatives_lanes},
#endif
#ifdef RBDC_HOT_WANTS_forward_dynamics_derivatives
    {"forward_dynamics_derivatives", hot_forward_dynamics_derivatives},
#endif
#ifdef RBDC_HOT_WANTS_forward_dynamics_derivatives_lanes
    {"forward_dynamics_derivatives_lanes", hot_forward_dynamics_derivatives_lanes},
#endif
};

// usage: hot_functions NAME CALLS [time]
int main(int argc, char** argv) {
  if (argc < 3) return 2;
  const long calls = std::atol(argv[2]);
  const bool time = argc > 3 && std::strcmp(argv[3], "time") == 0;
  static double states[64][3][20], out[at_df + g::nv * 3 * g::n_feet];  // the largest: ∂a/∂(q, v, τ, f)
  for (int s = 0; s < 64; ++s)
    for (int k = 0; k < 20; ++k)
      for (int j = 0; j < 3; ++j) states[s][j][k] = std::sin(1.0 + s * 0.37 + k * 1.3 + j * 0.71);
  for (int s = 0; s < 64; ++s) {  // unit quaternion
    double* q = states[s][0];
    const double n = std::sqrt(q[3] * q[3] + q[4] * q[4] + q[5] * q[5] + q[6] * q[6]);
    for (int k = 3; k < 7; ++k) q[k] /= n;
  }
  for (const Entry& e : entries) {
    if (std::strcmp(e.name, argv[1]) != 0) continue;
    double best = 1e30, sink = 0;
    for (int rep = 0; rep < (time ? 200 : 1); ++rep) {
      const auto start = std::chrono::steady_clock::now();
      for (long i = 0; i < calls; ++i) {
        const auto& s = states[i & 63];
        e.function(s[0], s[1], s[2], out);
        sink += out[i % 18];
      }
      const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
      if (ns / calls < best) best = ns / calls;
    }
    if (time) std::printf("%.1f\n", best);
    return sink == 12345.678 ? 1 : 0;
  }
  return 2;
}
