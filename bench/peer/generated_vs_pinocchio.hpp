// The two sides of generated_vs_pinocchio: Pinocchio 3 (pinocchio_side.cpp, robot-independent, compiled
// once) and rbdc's generated code for one robot (generated_side.cpp, compiled per robot). They meet
// only here, on dynamic Eigen types in rbdc's coordinates, so neither TU sees the other's headers.
#pragma once

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace rbdc {
struct Model;
}

namespace peer {

constexpr int kStates = 64;  ///< random states, cycled one per benchmark iteration

/// One state in rbdc's coordinates (docs/conventions.md); tau holds the 1-DoF joints' torques only.
struct State {
  Eigen::VectorXd q, v, a, tau;
};

/// Every compared quantity in rbdc's coordinates, whichever side computed it.
struct Outputs {
  Eigen::VectorXd tau, cg, g, a;  ///< ID (q, v, a), c + g, g, FD (q, v, tau, foot forces 0)
  Eigen::MatrixXd M, dtau_dq, dtau_dv, da_dq, da_dv;
  Eigen::MatrixXd da_dtau;  ///< nv × n_joints: M⁻¹Sᵀ
};

/// One side: its outputs at a state (for the agreement) and its benchmarks `<prefix>/<quantity>` for
/// the quantities ID, c+g, g, M, FD, dID, dFD.
class Side {
 public:
  virtual ~Side() = default;
  virtual Outputs outputs(const State& s) const = 0;
  /// `states` are converted to the side's own types once, here, outside the timed loops.
  virtual void register_benchmarks(const std::vector<State>& states) const = 0;
};

/// Pinocchio's model of `urdf`, its joints matched to `m`'s by name; `m` must outlive the side.
std::unique_ptr<Side> pinocchio_side(const rbdc::Model& m, const std::string& urdf);
/// The generated code the binary was compiled with; throws unless its dimensions are `m`'s.
std::unique_ptr<Side> generated_side(const rbdc::Model& m);
/// The generated robot's name (its namespace).
const char* generated_robot();

/// Registers benchmark `name`: iteration i calls `call(i mod kStates)`. A template, so that each
/// side's algorithm is inlined into its own loop.
template <class Call>
void add_benchmark(const std::string& name, Call call) {
  benchmark::RegisterBenchmark(name.c_str(), [call](benchmark::State& st) mutable {
    int k = 0;
    for (auto _ : st) {
      call(k);
      k = (k + 1) % kStates;
    }
  });
}

}  // namespace peer
