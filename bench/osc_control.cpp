// rbdc-osc-bench: the cost of the trot controller's pieces on the Mini Cheetah (paper 001 Sec. 6.1
// reports 13.1 µs for the recursion, 173 µs for the closed form and 12.6 µs for the control law
// of Eqs. 53 and 55 on a 2.3 GHz i5). States are taken from a trot at mid-stance of each pair.
#include <benchmark/benchmark.h>

#include <vector>

#include "rbdc/control/osc_trot.hpp"
#include "rbdc/control/trunk_dynamics.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/run.hpp"

namespace {

using namespace rbdc;
using namespace rbdc::control;

struct TrotState {
  VectorX q, v;
  FeetForces f;
  Matrix3X f_measured;  ///< f as the controller interface takes it
  double t = 0;
};

// States along a short OSC trot, sampled every 7 ms once it is under way (after 1 s).
const std::vector<TrotState>& trot_states() {
  static const std::vector<TrotState> states = [] {
    const Model model = sim::load_robot(sim::default_urdf());
    std::unique_ptr<sim::DynamicsModel> dynamics = sim::make_generated_dynamics();
    sim::Simulator simulator(*dynamics, sim::SimOptions{});
    OscTrotController controller(model, TrotParameters{}, StanceControl::OperationalSpace, 0.02);
    sim::RunOptions run;
    run.duration = 1.5;
    run.sample_interval = 7e-3;
    std::vector<TrotState> out;
    sim::RunCallbacks callbacks;
    callbacks.sample = [&](sim::Simulator& s) {
      if (s.time() <= 1.0) return;
      Matrix3X f;
      sim::world_forces(s.contacts(), f);
      out.push_back({s.q(), s.v(), f, f, s.time()});
    };
    sim::run(simulator, controller, run, callbacks);
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
  OscReferenceData closed_form(model());
  const std::vector<int> feet = {0, 3};
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    benchmark::DoNotOptimize(
        osc_closed_form_constrained(model(), data, closed_form, s.q, s.v, feet).b.data());
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
  OscTrotController controller(model(), TrotParameters{}, control, 0.02);
  std::size_t i = 0;
  for (auto _ : state) {
    const TrotState& s = states[i++ % states.size()];
    benchmark::DoNotOptimize(controller.update({s.t, 1e-4, s.q, s.v, s.f_measured}).data());
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
