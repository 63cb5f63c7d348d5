// One adapter struct per generated robot (rbdc_bench/generated/<robot>.hpp) gives the benchmarks, the
// run-time-against-error study and the stress tests a single template parameter for "this robot's
// generated code": its dimensions and its raw-pointer functions (docs/generated_api.md), forwarded
// with the scalar deduced from the arguments. `has_osc` says whether the operational-space functions
// exist (floating base only).
#pragma once

#define RBDC_BENCH_FORWARD(ns, function)                         \
  template <class... Args>                                       \
  static void function(Args... args) noexcept {                  \
    ns::function(args...);                                       \
  }

/// The dimensions and the functions every generated robot of the full scene has.
#define RBDC_BENCH_GENERATED_CORE(ns, robot_name)                \
  static constexpr const char* name = robot_name;                \
  static constexpr int nq = ns::nq;                              \
  static constexpr int nv = ns::nv;                              \
  static constexpr int n_joints = ns::n_joints;                  \
  static constexpr int n_feet = ns::n_feet;                      \
  RBDC_BENCH_FORWARD(ns, feet_positions)                         \
  RBDC_BENCH_FORWARD(ns, feet_velocities)                        \
  RBDC_BENCH_FORWARD(ns, feet_jacobian)                          \
  RBDC_BENCH_FORWARD(ns, quadratic_velocity_terms)               \
  RBDC_BENCH_FORWARD(ns, gravity_terms)                          \
  RBDC_BENCH_FORWARD(ns, bias)                                   \
  RBDC_BENCH_FORWARD(ns, feet_force_terms)                       \
  RBDC_BENCH_FORWARD(ns, inverse_dynamics)                       \
  RBDC_BENCH_FORWARD(ns, mass_matrix)                            \
  RBDC_BENCH_FORWARD(ns, forward_dynamics)

/// The operational-space functions of a floating-base robot.
#define RBDC_BENCH_GENERATED_OSC(ns)                             \
  static constexpr bool has_osc = true;                          \
  RBDC_BENCH_FORWARD(ns, osc_open_chain)                         \
  RBDC_BENCH_FORWARD(ns, osc_closed_chain)
