#include "rbdc/control/command_line.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rbdc::control {

using sim::GroundPlane;
using sim::Integrator;
using sim::StateKind;
using sim::to_string;
namespace {

struct Option {
  std::string name;
  std::string value;  ///< metavariable; empty for a flag
  std::string help;
  std::function<void(const std::string&)> apply;
  std::function<std::string()> current;  ///< default shown by --help
};

double to_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value))
    throw std::invalid_argument("option " + option + ": '" + text + "' is not a number");
  return value;
}

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<Option> options(Program program, CommandLine& c) {
  std::vector<Option> list;
  auto number = [&](const std::string& name, double& target, const std::string& help) {
    list.push_back({name, "X", help, [&target, name](const std::string& t) { target = to_number(name, t); },
                    [&target] { return show(target); }});
  };
  auto text = [&](const std::string& name, std::string& target, const std::string& meta,
                  const std::string& help) {
    list.push_back({name, meta, help, [&target](const std::string& t) { target = t; },
                    [&target] { return target.empty() ? std::string("-") : target; }});
  };
  auto flag = [&](const std::string& name, bool& target, bool value, const std::string& help) {
    list.push_back({name, "", help, [&target, value](const std::string&) { target = value; }, nullptr});
  };
  number("--duration", c.run.duration, "simulated time, s");
  number("--dt", c.sim.dt, "time step, s");
  list.push_back({"--integrator", "heun|rk4|semi-implicit", "integration method",
                  [&c = c](const std::string& t) {
                    if (t == "heun") c.sim.integrator = Integrator::Heun;
                    else if (t == "rk4") c.sim.integrator = Integrator::RK4;
                    else if (t == "semi-implicit") c.sim.integrator = Integrator::SemiImplicitEuler;
                    else throw std::invalid_argument("option --integrator: unknown method '" + t + "'");
                  },
                  [&c = c] { return std::string(to_string(c.sim.integrator)); }});
  list.push_back({"--state", "quaternion|euler", "trunk orientation in the state (euler: Eqs. 41-42)",
                  [&c = c](const std::string& t) {
                    if (t == "quaternion") c.sim.state = StateKind::Quaternion;
                    else if (t == "euler") c.sim.state = StateKind::Euler;
                    else throw std::invalid_argument("option --state: unknown state '" + t + "'");
                  },
                  [&c = c] { return std::string(to_string(c.sim.state)); }});
  list.push_back({"--rotors", "full|armature|none",
                  "the drive train: MIT's rotors as bodies (full), as reflected inertia on M's diagonal "
                  "(armature), or none (paper 000); rbdc-sim: armature needs --dynamics runtime; "
                  "rbdc-mujoco-compare: MuJoCo gets the armature",
                  [&c = c](const std::string& t) {
                    if (t != "full" && t != "armature" && t != "none")
                      throw std::invalid_argument("option --rotors: unknown value '" + t + "'");
                    c.rotors = t;
                  },
                  [&c = c] { return c.rotors; }});
  if (program == Program::Sim) {
    list.push_back({"--dynamics", "generated|runtime",
                    "dynamics implementation: generated (the bundled Mini Cheetah) or runtime (any URDF)",
                    [&c = c](const std::string& t) {
                      if (t != "generated" && t != "runtime")
                        throw std::invalid_argument("option --dynamics: unknown implementation '" + t + "'");
                      c.dynamics = t;
                    },
                    [&c = c] { return c.dynamics; }});
    text("--out", c.out, "FILE.csv", "write the time series as CSV");
    flag("--profile", c.profile, true, "time dynamics, contact, integration and control separately");
  } else {
    text("--out", c.out, "DIR", "output directory for the CSVs, the table and the plots");
    flag("--no-plots", c.plots, false, "do not run mujoco/plot_compare.py");
    flag("--no-timing", c.timing, false, "skip the two unsampled runs that time both simulators");
    number("--mj-stiffness", c.mj_stiffness, "MuJoCo contact stiffness, N/m (solref -stiffness)");
    number("--mj-damping", c.mj_damping, "MuJoCo contact damping, N/(m/s) (solref -damping)");
    number("--mj-friction", c.mj_friction, "MuJoCo sliding friction coefficient");
    flag("--original-inertia", c.balanced_inertia, false,
         "ours on MIT's thigh inertia instead of MuJoCo's balanced one");
  }
  text("--urdf", c.urdf, "FILE", "robot URDF (feet LF_foot, RF_foot, LH_foot, RH_foot)");
  number("--sample-interval", c.run.sample_interval, "s between CSV rows");
  flag("--progress", c.run.progress, true, "print the state every simulated second (stderr)");
  flag("--quiet", c.run.progress, false, "no progress lines");
  // Contact model (Section 5, Table I).
  number("--stiffness", c.sim.contact.stiffness, "Hertz stiffness K, N/length-unit^e");
  number("--exponent", c.sim.contact.exponent, "Hertz exponent e");
  number("--length-unit", c.sim.contact.length_unit, "unit of the penetration in the Hertz law, m");
  number("--damping", c.sim.contact.damping, "nominal contact damping c_max, N/(m/s)");
  number("--ramp-distance", c.sim.contact.ramp_distance, "damping ramp-up distance w, m");
  number("--mu-static", c.sim.contact.mu_static, "static friction coefficient mu_s");
  number("--v-static", c.sim.contact.v_static, "stiction velocity v_s, m/s");
  number("--mu-dynamic", c.sim.contact.mu_dynamic, "sliding friction coefficient mu_d");
  number("--v-dynamic", c.sim.contact.v_dynamic, "stiction-sliding transition velocity v_d, m/s");
  number("--foot-radius", c.sim.contact.foot_radius, "foot sphere radius r, m");
  // Two-way choices: name, the two spellings, the target and its value for the first spelling.
  auto choice = [&](const std::string& name, const std::string& first, const std::string& second,
                    bool& target, const std::string& help) {
    list.push_back({name, first + "|" + second, help,
                    [&target, name, first, second](const std::string& t) {
                      if (t != first && t != second)
                        throw std::invalid_argument("option " + name + ": unknown value '" + t + "'");
                      target = t == first;
                    },
                    [&target, first, second] { return target ? first : second; }});
  };
  choice("--contact-point", "on", "off", c.contact_point,
         "on: force at the contact point C_k with its moment, friction from v_Ck (Eqs. 32-33); "
         "off: at the sphere centre");
  choice("--friction", "per-axis", "isotropic", c.friction_per_axis,
         "Eq. 38 on each tangential axis, or mu(|v_t|) against the slip direction");
  choice("--friction-update", "implicit", "explicit", c.friction_implicit,
         "friction stepped with the contact-space inertia (stable at Table I's v_s) or explicitly");
  number("--ground-tilt", c.ground_tilt_deg, "ground plane tilt about world x, deg");
  // Gait and gains (Section 6.2, Table I).
  number("--period", c.gait.period, "gait period, s");
  number("--step-length", c.gait.step_length, "stance stroke, m");
  number("--step-height", c.gait.step_height, "swing apex height, m");
  number("--stance-height", c.gait.stance_height, "foot point below the hip in stance, m");
  number("--ramp-time", c.gait.ramp_time, "time over which the stride grows to full size, s");
  number("--kp", c.gains.kp, "PD proportional gain, N.m/rad");
  number("--kd", c.gains.kd, "PD derivative gain, N.m.s/rad");
  flag("--help", c.help, true, "show this help");
  return list;
}

}  // namespace

void parse_command_line(int argc, char** argv, Program program, CommandLine& cli) {
  const std::vector<Option> list = options(program, cli);
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const Option* match = nullptr;
    for (const Option& o : list)
      if (o.name == arg) match = &o;
    if (match == nullptr) throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
    if (match->value.empty()) {
      match->apply("");
    } else {
      if (i + 1 >= argc) throw std::invalid_argument("option " + arg + " needs a value");
      match->apply(argv[++i]);
    }
  }
  if (!(cli.sim.dt > 0) || !(cli.run.duration >= 0))
    throw std::invalid_argument("--dt must be positive and --duration not negative");
  cli.sim.ground = GroundPlane::tilted_about_x(cli.ground_tilt_deg * M_PI / 180);
  sim::ContactParameters& contact = cli.sim.contact;
  contact.at_contact_point = cli.contact_point;
  contact.friction = cli.friction_per_axis ? sim::FrictionModel::PerAxis : sim::FrictionModel::Isotropic;
  contact.friction_update = cli.friction_implicit ? sim::FrictionUpdate::Implicit : sim::FrictionUpdate::Explicit;
}

std::string usage(Program program, const CommandLine& defaults) {
  CommandLine copy = defaults;
  std::ostringstream out;
  if (program == Program::Sim)
    out << "rbdc-sim: Mini Cheetah trot with the compliant contact of paper 000 (Sections 5-6).\n"
           "Runs the trot, prints wall time and real-time factor, optionally writes a CSV\n"
           "(t, x, y, z, roll, pitch, yaw, joint angles, joint velocities, then per foot contact\n"
           "activation and world contact force).\n\nUsage: rbdc-sim [options]\n\n";
  else
    out << "rbdc-mujoco-compare: the same trot in our simulator and in MuJoCo (paper 000 Section 6.3);\n"
           "reports trunk-pose MAE, left-foreleg contact agreement and normal-force MAE, wall times,\n"
           "writes both time series and the figures.\n\nUsage: rbdc-mujoco-compare [options]\n\n";
  for (const Option& o : options(program, copy)) {
    std::string head = "  " + o.name + (o.value.empty() ? "" : " " + o.value);
    if (head.size() < 34) head.resize(34, ' ');
    out << head << ' ' << o.help;
    if (o.current) out << " [" << o.current() << "]";
    out << '\n';
  }
  return out.str();
}

}  // namespace rbdc::control
