// Command-line options of the PD-trot programs rbdc-sim and rbdc-mujoco-compare: run, dynamics,
// contact, gait and gains. Every contact parameter of Table I is an option.
#pragma once

#include <string>

#include "rbdc/control/pd_trot.hpp"
#include "rbdc/sim/run.hpp"
#include "rbdc/sim/simulator.hpp"

namespace rbdc::control {

struct CommandLine {
  sim::SimOptions sim;
  GaitParameters gait;
  PdGains gains;
  sim::RunOptions run;
  std::string urdf;               ///< robot file
  std::string dynamics = "generated";  ///< generated | runtime (falls back to runtime when absent)
  std::string out;                ///< CSV output (rbdc-sim) or output directory (comparison)
  double ground_tilt_deg = 0;     ///< ground plane tilt about world x
  bool profile = false;
  bool plots = true;              ///< comparison: draw PNGs with matplotlib
  bool help = false;
};

enum class Program { Sim, Compare };
/// Parses argv into `cli` (which holds the defaults); each program accepts its own extra options.
/// Throws std::invalid_argument naming the option and the problem.
void parse_command_line(int argc, char** argv, Program program, CommandLine& cli);
std::string usage(Program program, const CommandLine& defaults);

}  // namespace rbdc::control
