#include "rbdc/sim/trot_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace rbdc::sim {

RunSummary run_trot(Simulator& simulator, TrotController& controller, const RunOptions& options,
                    const std::function<void(Simulator&)>& sample) {
  using Clock = std::chrono::steady_clock;
  const double dt = simulator.options().dt;
  simulator.reset(controller.standing_configuration(), VectorX::Zero(simulator.v().size()));
  const long steps = std::lround(options.duration / dt);
  const long sample_every =
      options.sample_interval > 0 ? std::max(1L, std::lround(options.sample_interval / dt)) : 0;
  const long progress_every = std::lround(1.0 / dt);
  RunSummary summary;
  summary.min_trunk_height = simulator.q()[2];
  if (sample) sample(simulator);
  const Clock::time_point start = Clock::now();
  for (long n = 1; n <= steps; ++n) {
    Clock::time_point control_start;
    if (simulator.profiling()) control_start = Clock::now();
    const VectorX& tau = controller.update(dt, simulator.q(), simulator.v());
    if (simulator.profiling())
      simulator.profile().control += std::chrono::duration<double>(Clock::now() - control_start).count();
    simulator.step(tau);
    summary.min_trunk_height = std::min(summary.min_trunk_height, simulator.q()[2]);
    if (!simulator.q().allFinite() || !simulator.v().allFinite()) {
      summary.finite = false;
      summary.steps = n;
      break;
    }
    if (sample && n % sample_every == 0) sample(simulator);
    if (options.progress && n % progress_every == 0)
      std::fprintf(stderr, "  t = %5.2f s   x = %7.3f m   z = %6.3f m\n", simulator.time(),
                   simulator.q()[0], simulator.q()[2]);
    summary.steps = n;
  }
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace rbdc::sim
