// One trot run of the Mini Cheetah in the paper-000 simulator (sim::run) under one stance
// controller at a fixed control period, scored the way paper 001 Sec. 6.2 reports it: roll and
// pitch during stance, falls.
#pragma once

#include <string>

#include "rbdc/control/osc_trot.hpp"
#include "rbdc/sim/simulator.hpp"

namespace rbdc::control {

struct ExperimentOptions {
  double duration = 10;        ///< s
  double control_period = 1e-4;  ///< s between controller updates (every simulation step)
  sim::SimOptions sim;
  TrotParameters trot;
  StanceControl control = StanceControl::OperationalSpace;
  std::string trace_csv;       ///< per-millisecond trace (empty: none)
};

/// Mean and maximum of |x| over the samples added.
struct AbsStats {
  void add(double x);
  double mean() const { return count ? sum / count : 0; }
  double sum = 0, max = 0;
  long count = 0;
};

struct ExperimentResult {
  AbsStats roll_error, pitch_error;  ///< |γ − γ_d|, |β − β_d| during stance control, deg
  AbsStats roll, pitch;              ///< |γ|, |β| during stance control, deg
  bool fell = false;
  double fall_time = 0;              ///< s, first time a fall criterion held
  std::string fall_reason;
  double mean_speed = 0;             ///< m/s, forward, over the second half of the run
  double controller_seconds = 0;     ///< wall time inside OscTrotController::update
  long controller_calls = 0;
  double simulated = 0;              ///< s
};

/// A fall: trunk origin below 0.12 m, |roll| or |pitch| beyond 45°, or a non-finite state.
ExperimentResult run_trot_experiment(const Model& model, sim::DynamicsModel& dynamics,
                                     const ExperimentOptions& options);

}  // namespace rbdc::control
