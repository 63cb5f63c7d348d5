// rbdc-osc-trot: the Mini Cheetah trot of paper 001 Sec. 6.2 in rbdc's simulator under the
// operational-space controllers (closed chain, open chain with measured forces) and the
// Raibert-style hip-torque controller; prints one table row per controller.
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rbdc/control/drive_train.hpp"
#include "rbdc/control/trot_experiment.hpp"
#include "rbdc/result_file.hpp"
#include "rbdc/sim/robot.hpp"

using namespace rbdc;
using namespace rbdc::control;

namespace {

struct Options {
  std::vector<StanceControl> controllers = {StanceControl::OperationalSpace,
                                            StanceControl::OperationalSpaceOpenChain,
                                            StanceControl::HipTorque};
  ExperimentOptions experiment;
  std::string out;
  bool rotors = false;  ///< the plant with MIT's rotors (the controller's recursions stay without)
};

const char* kUsage =
    "usage: rbdc-osc-trot [--controller osc|osc-open|raibert|all] [--duration S] [--speed M/S]\n"
    "                     [--control-period S] [--set NAME=VALUE]... [--out DIR] [--rotors full|none]\n"
    "Runs the Mini Cheetah trot under each controller and reports roll/pitch tracking during\n"
    "stance, falls and the controller's cost per call. --out writes DIR/<controller>.csv traces\n"
    "and DIR/summary.md. --rotors full simulates the robot with MIT's twelve rotors as bodies\n"
    "(generated/mini_cheetah_rotors); the controllers' trunk recursions do not model them.\n";

double number(const char* option, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0))
    throw std::invalid_argument(std::string(option) + ": expected a positive number, got '" + text + "'");
  return value;
}

// --set NAME=VALUE for the scalar trot parameters (tuning without recompiling).
void set_assignment(TrotParameters& p, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq != std::string::npos) {
    char* end = nullptr;
    const double value = std::strtod(assignment.c_str() + eq + 1, &end);
    if (*end == '\0') {
      try {
        set_parameter(p, assignment.substr(0, eq), value);
        return;
      } catch (const std::invalid_argument&) {
        // an unknown name: reported below with the whole assignment
      }
    }
  }
  throw std::invalid_argument("--set: expected NAME=NUMBER with a trot parameter name, got '" +
                              assignment + "'");
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (i + 1 >= argc) throw std::invalid_argument("unknown option or missing value: '" + arg + "'");
    const char* value = argv[++i];
    if (arg == "--controller") {
      if (std::strcmp(value, "all") != 0) o.controllers = {parse_stance_control(value)};
    } else if (arg == "--duration") {
      o.experiment.duration = number("--duration", value);
    } else if (arg == "--speed") {
      o.experiment.trot.speed = number("--speed", value);
    } else if (arg == "--control-period") {
      o.experiment.control_period = number("--control-period", value);
    } else if (arg == "--set") {
      set_assignment(o.experiment.trot, value);
    } else if (arg == "--out") {
      o.out = value;
    } else if (arg == "--rotors") {
      if (std::strcmp(value, "full") != 0 && std::strcmp(value, "none") != 0)
        throw std::invalid_argument(std::string("--rotors: expected full or none, got '") + value + "'");
      o.rotors = std::strcmp(value, "full") == 0;
    } else {
      throw std::invalid_argument("unknown option '" + arg + "'");
    }
  }
  return o;
}

std::string row(StanceControl control, const ExperimentResult& r) {
  char fall[64];
  if (r.fell)
    std::snprintf(fall, sizeof fall, "at %.2f s", r.fall_time);
  else
    std::snprintf(fall, sizeof fall, "no");
  char line[512];
  std::snprintf(line, sizeof line,
                "| %-8s | %6.3f / %6.3f | %6.3f / %6.3f | %6.3f / %6.3f | %6.3f / %6.3f | %-10s | %5.2f | %6.2f |",
                to_string(control), r.roll_error.mean(), r.roll_error.max, r.pitch_error.mean(),
                r.pitch_error.max, r.roll.mean(), r.roll.max, r.pitch.mean(), r.pitch.max, fall,
                r.mean_speed, 1e6 * r.controller_seconds / std::max(1L, r.controller_calls));
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Options o = parse(argc, argv);
    const Model model = load_trot_robot("", o.rotors ? ActuatorMode::Full : ActuatorMode::None);
    std::unique_ptr<sim::DynamicsModel> dynamics =
        o.rotors ? sim::make_generated_rotor_dynamics() : sim::make_generated_dynamics();
    if (!o.out.empty()) std::filesystem::create_directories(o.out);
    const TrotParameters& trot = o.experiment.trot;
    char header[512];
    std::snprintf(header, sizeof header,
                  "Mini Cheetah trot at %.2f m/s desired (step %.3f s, duty 0.5), %.1f s, %s dynamics, "
                  "dt = %g s, control every %g s\n\n"
                  "| control  | roll err mean/max (deg) | pitch err mean/max (deg) | |roll| mean/max (deg) "
                  "| |pitch| mean/max (deg) | fell       | v (m/s) | us/call |\n"
                  "|---|---|---|---|---|---|---|---|\n",
                  trot.speed, trot.step_duration, o.experiment.duration, dynamics->name().c_str(),
                  o.experiment.sim.dt, o.experiment.control_period);
    std::string table = header;
    std::fputs(header, stdout);
    for (StanceControl control : o.controllers) {
      ExperimentOptions e = o.experiment;
      e.control = control;
      if (!o.out.empty()) e.trace_csv = o.out + "/" + to_string(control) + ".csv";
      const ExperimentResult r = run_trot_experiment(model, *dynamics, e);
      const std::string line = row(control, r);
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
      table += line + "\n";
      if (r.fell) std::fprintf(stderr, "rbdc-osc-trot: %s fell at %.3f s: %s\n", to_string(control),
                               r.fall_time, r.fall_reason.c_str());
    }
    if (!o.out.empty()) write_result_file(o.out + "/summary.md", table);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbdc-osc-trot: %s\n", e.what());
    return 1;
  }
}
