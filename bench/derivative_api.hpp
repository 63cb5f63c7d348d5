// The adapter struct of one robot's generated derivatives scene (generated/<robot>/derivatives): its
// dimensions and raw-pointer functions, forwarded with the scalar deduced from the arguments, so that
// the derivative cases (derivative_quantities.hpp) take one template parameter per robot.
#pragma once

#include "rbdc_bench/generated_api.hpp"

/// The members of `struct Api` for the namespace `ns` (rbdc_gen::<robot>::derivatives).
#define RBDC_BENCH_DERIVATIVE_API(ns, robot_name)                \
  static constexpr const char* name = robot_name;                \
  static constexpr int nq = ns::nq;                              \
  static constexpr int nv = ns::nv;                              \
  static constexpr int n_joints = ns::n_joints;                  \
  static constexpr int n_feet = ns::n_feet;                      \
  RBDC_BENCH_FORWARD(ns, inverse_dynamics)                       \
  RBDC_BENCH_FORWARD(ns, forward_dynamics)                       \
  RBDC_BENCH_FORWARD(ns, gravity_terms)                          \
  RBDC_BENCH_FORWARD(ns, feet_velocities)                        \
  RBDC_BENCH_FORWARD(ns, feet_force_terms)                       \
  RBDC_BENCH_FORWARD(ns, inverse_dynamics_derivatives)           \
  RBDC_BENCH_FORWARD(ns, forward_dynamics_derivatives)           \
  RBDC_BENCH_FORWARD(ns, bias_derivatives)                       \
  RBDC_BENCH_FORWARD(ns, gravity_derivatives)                    \
  RBDC_BENCH_FORWARD(ns, feet_velocity_derivatives)              \
  RBDC_BENCH_FORWARD(ns, feet_force_term_derivatives)
