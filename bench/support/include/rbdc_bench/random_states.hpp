// Reproducible random states for benchmarks and stress tests. Every state is drawn from a seeded
// std::mt19937_64, so a run can be repeated exactly; benchmarks cycle through a pre-generated set so
// that no call sees the inputs of the previous one.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "rbdc/data.hpp"

namespace rbdc_bench {

/// One full set of inputs for every quantity: q (nq), v, a (nv), τ (n_joints), foot forces (3 × n_feet).
struct State {
  rbdc::VectorX q, v, a, tau;
  rbdc::Matrix3X f;
};

struct StateRanges {
  double joint_velocity = 10.0;      ///< |q̇_i| ≤ this, rad/s or m/s
  double trunk_velocity = 2.0;       ///< |ω_B|, |v_B| components ≤ this
  double acceleration = 20.0;        ///< |a_i| ≤ this
  double torque = 20.0;              ///< |τ_i| ≤ this, N·m
  double foot_force = 60.0;          ///< |f| components ≤ this, N (z pushes up: 0 … foot_force)
  bool within_joint_limits = true;   ///< joint angles within URDF limits (else [-π, π])
  /// When not empty: (lower, upper) per 1-DoF joint (joint i at entry i-1), overriding the above.
  std::vector<std::pair<double, double>> joint_ranges;
};

/// `count` states drawn with `seed`: uniform joint angles, a uniformly random unit quaternion, a
/// trunk position in [-1, 1]³, uniform rates, accelerations, torques and foot forces.
std::vector<State> random_states(const rbdc::Model& model, int count, std::uint64_t seed,
                                 const StateRanges& ranges = {});

/// Column-major copies of a state set in scalar T, one contiguous block per argument, for the
/// generated code's raw-pointer overloads (state k of q starts at q.data() + k * nq).
template <class T>
struct StateArrays {
  int count = 0, nq = 0, nv = 0, n_joints = 0, n_feet = 0;
  std::vector<T> q, v, a, tau, f;

  const T* q_at(int k) const { return q.data() + static_cast<std::ptrdiff_t>(k) * nq; }
  const T* v_at(int k) const { return v.data() + static_cast<std::ptrdiff_t>(k) * nv; }
  const T* a_at(int k) const { return a.data() + static_cast<std::ptrdiff_t>(k) * nv; }
  const T* tau_at(int k) const { return tau.data() + static_cast<std::ptrdiff_t>(k) * n_joints; }
  const T* f_at(int k) const { return f.data() + static_cast<std::ptrdiff_t>(k) * 3 * n_feet; }
};

template <class T>
StateArrays<T> to_arrays(const std::vector<State>& states) {
  StateArrays<T> out;
  out.count = static_cast<int>(states.size());
  if (states.empty()) return out;
  out.nq = static_cast<int>(states[0].q.size());
  out.nv = static_cast<int>(states[0].v.size());
  out.n_joints = static_cast<int>(states[0].tau.size());
  out.n_feet = static_cast<int>(states[0].f.cols());
  auto append = [](std::vector<T>& dst, const double* src, Eigen::Index n) {
    for (Eigen::Index i = 0; i < n; ++i) dst.push_back(static_cast<T>(src[i]));
  };
  for (const State& s : states) {
    append(out.q, s.q.data(), s.q.size());
    append(out.v, s.v.data(), s.v.size());
    append(out.a, s.a.data(), s.a.size());
    append(out.tau, s.tau.data(), s.tau.size());
    append(out.f, s.f.data(), s.f.size());
  }
  return out;
}

}  // namespace rbdc_bench
