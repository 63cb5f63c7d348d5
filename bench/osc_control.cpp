// rbdc-osc-bench: the cost of the trot controller's pieces on the Mini Cheetah (paper 001 Sec. 6.1
// reports 13.1 µs for the recursion, 173 µs for the closed form and 12.6 µs for the control law
// of Eqs. 53 and 55 on a 2.3 GHz i5). States are taken from a trot at mid-stance of each pair.
#include <benchmark/benchmark.h>

#include <vector>

#include "rbdc/control/trot_experiment.hpp"
#include "rbdc/control/trunk_dynamics.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/sim/robot.hpp"

namespace {

using namespace rbdc;
using namespace rbdc::control;

struct TrotState {
  VectorX q, v;
  FeetForces f;
  double t = 0;
};

// States along a short OSC trot, sampled every 7 ms once it is under way.
const std::vector<TrotState>& trot_states() {
  static const std::vector<TrotState> states = [] {
    const Model model = sim::load_robot(sim::default_urdf());
    std::unique_ptr<sim::DynamicsModel> dynamics = sim::make_generated_dynamics();
    if (!dynamics) dynamics = sim::make_runtime_dynamics(model);
    sim::Simulator simulator(*dynamics, sim::SimOptions{});
    TrotController controller(model, TrotParameters{}, StanceControl::OperationalSpace, 0.02);
    simulator.reset(controller.standing_configuration(), VectorX::Zero(kNv));
    std::vector<TrotState> out;
    for (long n = 0; n < 15000; ++n) {
      FeetForces f;
      for (int k = 0; k < kFeet; ++k) f.col(k) = simulator.contacts()[k].force_W;
      const JointTorques tau = controller.update(simulator.time(), simulator.q().data(), simulator.v().data(), f);
      if (n > 10000 && n % 70 == 0) out.push_back({simulator.q(), simulator.v(), f, simulator.time()});
      simulator.step(tau);
    }
    return out;
  }();
  return states;
}

const Model& model() {
  static const Model m = sim::load_robot(sim::default_urdf());
  return m;
}

void BM_closed_chain_recursion_generated(benchmark::State& state) {
  const auto& states = trot_states();
  TrunkTaskDynamics d;
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    closed_chain_dynamics(s.q.data(), s.v.data(), StancePair::LfRh, mini_cheetah_ground_mass(), d);
    benchmark::DoNotOptimize(d);
  }
}

void BM_open_chain_recursion_generated(benchmark::State& state) {
  const auto& states = trot_states();
  TrunkTaskDynamics d;
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    open_chain_dynamics(s.q.data(), s.v.data(), s.f, d);
    benchmark::DoNotOptimize(d);
  }
}

void BM_closed_chain_recursion_runtime(benchmark::State& state) {
  const auto& states = trot_states();
  Data data(model());
  const std::vector<int> feet = {0, 3};
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    benchmark::DoNotOptimize(osc_closed_chain(model(), data, s.q, s.v, feet).b.data());
  }
}

void BM_closed_form_runtime(benchmark::State& state) {
  const auto& states = trot_states();
  Data data(model());
  const std::vector<int> feet = {0, 3};
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    benchmark::DoNotOptimize(osc_closed_form_constrained(model(), data, s.q, s.v, feet).b.data());
  }
}

// Eqs. 53 and 55 alone (LDLT of Λ, SVD of the weighted 6 × 6 stance Jacobian).
void BM_stance_law(benchmark::State& state) {
  const auto& states = trot_states();
  std::vector<TrunkTaskDynamics> dynamics(states.size());
  for (std::size_t k = 0; k < states.size(); ++k)
    closed_chain_dynamics(states[k].q.data(), states[k].v.data(), StancePair::LfRh,
                          mini_cheetah_ground_mass(), dynamics[k]);
  const JointTorques tau_swing = JointTorques::Constant(0.5), tau_passive = JointTorques::Constant(-1.0);
  StanceTorques out;
  std::size_t i = 0;
  for (auto _ : state) {
    operational_space_stance_torques<6>(dynamics[i++ % dynamics.size()], {0, 1, 2, 9, 10, 11},
                                        tau_swing, tau_passive, Eigen::Vector2d(1, -1),
                                        default_task_weights(), out);
    benchmark::DoNotOptimize(out.tau);
  }
}

// One whole controller update (feet kinematics, Jacobian, footsteps, swing servo, virtual legs and
// the stance law with its recursion) as called at every control tick.
void BM_controller_update(benchmark::State& state) {
  const auto& states = trot_states();
  const StanceControl control = static_cast<StanceControl>(state.range(0));
  state.SetLabel(to_string(control));
  TrotController controller(model(), TrotParameters{}, control, 0.02);
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    benchmark::DoNotOptimize(controller.update(s.t, s.q.data(), s.v.data(), s.f).data());
  }
}

BENCHMARK(BM_closed_chain_recursion_generated);
BENCHMARK(BM_open_chain_recursion_generated);
BENCHMARK(BM_closed_chain_recursion_runtime);
BENCHMARK(BM_closed_form_runtime);
BENCHMARK(BM_stance_law);
BENCHMARK(BM_controller_update)
    ->Arg(static_cast<int>(StanceControl::OperationalSpace))
    ->Arg(static_cast<int>(StanceControl::OperationalSpaceOpenChain))
    ->Arg(static_cast<int>(StanceControl::HipTorque));

}  // namespace

BENCHMARK_MAIN();
