// One trot run: the controller (zero-order hold at the simulation step) driving the simulator,
// with a sample callback at a fixed interval. Shared by rbdc-sim, the tests and the comparison.
#pragma once

#include <functional>

#include "rbdc/sim/simulator.hpp"
#include "rbdc/sim/trot.hpp"

namespace rbdc::sim {

struct RunOptions {
  double duration = 10.0;       ///< s
  double sample_interval = 1e-3;  ///< s between samples (0: none)
  bool progress = false;        ///< a line on stderr every simulated second
};

struct RunSummary {
  double wall_seconds = 0;
  long steps = 0;
  bool finite = true;        ///< no NaN/inf appeared in the state
  double min_trunk_height = 0;  ///< lowest trunk-origin height over the run, m
};

/// Starts from the controller's standing configuration at rest and runs for options.duration,
/// calling `sample(simulator)` at t = 0 and every sample_interval. Stops early on a non-finite state.
RunSummary run_trot(Simulator& simulator, TrotController& controller, const RunOptions& options,
                    const std::function<void(Simulator&)>& sample = {});

}  // namespace rbdc::sim
