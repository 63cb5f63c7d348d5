#include "rbdc/sim/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace rbdc::sim {

RunSummary run(Simulator& simulator, Controller& controller, const RunOptions& options,
               const RunCallbacks& callbacks) {
  using Clock = std::chrono::steady_clock;
  const double dt = simulator.options().dt;
  simulator.reset(controller.initial_configuration(), VectorX::Zero(simulator.v().size()));
  const long steps = std::lround(options.duration / dt);
  const long control_every = std::max(1L, std::lround(options.control_period / dt));
  const long sample_every =
      options.sample_interval > 0 ? std::max(1L, std::lround(options.sample_interval / dt)) : 0;
  const long progress_every = std::lround(1.0 / dt);
  Matrix3X forces;  // stays empty for controllers that do not read them
  RunSummary summary;
  summary.min_trunk_height = simulator.q()[2];
  VectorX tau;
  const Clock::time_point start = Clock::now();
  // Step n goes from t = n·dt to (n + 1)·dt; the controller and the samples see the state at n·dt.
  for (long n = 0;; ++n) {
    if (n < steps && n % control_every == 0) {
      if (controller.uses_foot_forces()) world_forces(simulator.contacts(), forces);
      const ControllerInput input{simulator.time(), control_every * dt, simulator.q(), simulator.v(),
                                  forces};
      const Clock::time_point update_start = Clock::now();
      tau = controller.update(input);
      summary.controller_seconds += std::chrono::duration<double>(Clock::now() - update_start).count();
      ++summary.controller_calls;
      if (callbacks.updated) callbacks.updated(simulator);
    }
    if (callbacks.sample && sample_every && n % sample_every == 0) callbacks.sample(simulator);
    if (n == steps) break;
    simulator.step(tau);
    summary.steps = n + 1;
    summary.min_trunk_height = std::min(summary.min_trunk_height, simulator.q()[2]);
    if (!simulator.q().allFinite() || !simulator.v().allFinite()) {
      summary.finite = false;
      break;
    }
    if (callbacks.stop && (summary.stop_reason = callbacks.stop(simulator))) break;
    if (options.progress && (n + 1) % progress_every == 0)
      std::fprintf(stderr, "  t = %5.2f s   x = %7.3f m   z = %6.3f m\n", simulator.time(),
                   simulator.q()[0], simulator.q()[2]);
  }
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace rbdc::sim
