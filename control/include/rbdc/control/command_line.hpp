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
  std::string rotors = "none";    ///< full | armature | none (drive_train.hpp)
  std::string out;                ///< CSV output (rbdc-sim) or output directory (comparison)
  double ground_tilt_deg = 0;     ///< ground plane tilt about world x
  // Contact model choices, copied into sim.contact after parsing.
  bool contact_point = sim::ContactParameters{}.at_contact_point;
  bool friction_per_axis = sim::ContactParameters{}.friction == sim::FrictionModel::PerAxis;
  bool friction_implicit = sim::ContactParameters{}.friction_update == sim::FrictionUpdate::Implicit;
  bool profile = false;
  bool plots = true;              ///< comparison: draw PNGs with matplotlib
  // Comparison only: MuJoCo's contact (Table I's MuJoCo column) and what the ablations switch.
  double mj_stiffness = 1.6e3;    ///< N/m, solref = (−stiffness, −damping)
  double mj_damping = 100.0;      ///< N/(m/s)
  double mj_friction = 1.6;
  bool balanced_inertia = true;   ///< ours on MuJoCo's balanced thigh inertia (false: MIT's)
  bool timing = true;             ///< time both simulators without sampling (two more runs)
  bool help = false;
};

enum class Program { Sim, Compare };
/// Parses argv into `cli` (which holds the defaults); each program accepts its own extra options.
/// Throws std::invalid_argument naming the option and the problem.
void parse_command_line(int argc, char** argv, Program program, CommandLine& cli);
std::string usage(Program program, const CommandLine& defaults);

}  // namespace rbdc::control
