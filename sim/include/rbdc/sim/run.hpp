// The run loop of the simulator: any controller (controller.hpp) driving it with a zero-order hold
// of its torques between updates, optional sampling and stop callbacks. Used by rbdc-sim,
// rbdc-osc-trot, the MuJoCo comparison, the tests and the benchmarks.
#pragma once

#include <functional>

#include "rbdc/sim/controller.hpp"
#include "rbdc/sim/simulator.hpp"

namespace rbdc::sim {

struct RunOptions {
  double duration = 10.0;         ///< s
  double control_period = 0;      ///< s between controller updates (0: every step)
  double sample_interval = 1e-3;  ///< s between samples (0: none)
  bool progress = false;          ///< a line on stderr every simulated second
};

/// Optional callbacks; each sees the simulator at the current state.
struct RunCallbacks {
  std::function<void(Simulator&)> sample;     ///< at t = 0, every sample_interval and at the end
  std::function<void(Simulator&)> updated;    ///< right after each controller update
  std::function<const char*(Simulator&)> stop;  ///< after each step; a reason ends the run
};

struct RunSummary {
  double wall_seconds = 0;
  long steps = 0;
  bool finite = true;             ///< no NaN/inf appeared in the state
  const char* stop_reason = nullptr;  ///< what callbacks.stop returned, if it ended the run
  double min_trunk_height = 0;    ///< lowest trunk-origin height over the run, m
  double controller_seconds = 0;  ///< wall time inside Controller::update
  long controller_calls = 0;
};

/// Starts from the controller's initial configuration at rest and runs for options.duration.
/// Stops early on a non-finite state or when callbacks.stop gives a reason.
RunSummary run(Simulator& simulator, Controller& controller, const RunOptions& options,
               const RunCallbacks& callbacks = {});

}  // namespace rbdc::sim
