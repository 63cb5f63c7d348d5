// rbdc-sim: the 10 s Mini Cheetah trot of paper 000 on generated (or runtime) dynamics.
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>

#include "rbdc/control/command_line.hpp"
#include "rbdc/control/drive_train.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/trajectory_csv.hpp"

using namespace rbdc;
using namespace rbdc::control;
using namespace rbdc::sim;

int main(int argc, char** argv) {
  CommandLine cli;
  cli.run.progress = true;
  try {
    parse_command_line(argc, argv, Program::Sim, cli);
    if (cli.help) {
      std::fputs(usage(Program::Sim, CommandLine{}).c_str(), stdout);
      return 0;
    }
    const ActuatorMode drive_train = parse_actuator_mode(cli.rotors);
    const Model model = load_trot_robot(cli.urdf, drive_train);
    if (drive_train == ActuatorMode::Armature && cli.dynamics == "generated") {
      std::fprintf(stderr, "rbdc-sim: --rotors armature has no generated dynamics (no bundled scene with "
                           "actuators: armature): add --dynamics runtime\n");
      return 1;
    }
    std::unique_ptr<DynamicsModel> dynamics;
    if (cli.dynamics == "runtime")
      dynamics = make_runtime_dynamics(model);
    else if (drive_train == ActuatorMode::Full)
      dynamics = make_generated_rotor_dynamics();
    else
      dynamics = make_generated_dynamics();
    if (dynamics->nq() != model.nq || dynamics->n_feet() != static_cast<int>(model.feet.size())) {
      std::fprintf(stderr, "rbdc-sim: the %s dynamics do not match the robot in the URDF\n",
                   dynamics->name().c_str());
      return 1;
    }
    Simulator simulator(*dynamics, cli.sim);
    simulator.set_profiling(cli.profile);
    PdTrotController controller(model, cli.gait, cli.gains, cli.sim.contact.foot_radius);
    std::optional<TrajectoryCsv> csv;
    if (!cli.out.empty()) csv.emplace(cli.out, model);
    std::fprintf(stderr, "rbdc-sim: %s dynamics, rotors %s, %s, %s state, dt = %g s, %g s\n",
                 dynamics->name().c_str(), cli.rotors.c_str(), to_string(cli.sim.integrator),
                 to_string(cli.sim.state), cli.sim.dt, cli.run.duration);
    RunCallbacks callbacks;
    if (csv) callbacks.sample = [&](Simulator& s) { csv->write(s.time(), s.q(), s.v(), s.contacts()); };
    const RunSummary summary = run(simulator, controller, cli.run, callbacks);
    if (csv) csv->finish();
    const double simulated = summary.steps * cli.sim.dt;
    std::printf("simulated %.3f s in %.3f s wall: real-time factor %.1f (%ld steps, %.2f us/step)\n",
                simulated, summary.wall_seconds, simulated / summary.wall_seconds, summary.steps,
                1e6 * summary.wall_seconds / summary.steps);
    std::printf("trunk: x = %.3f m, y = %.3f m, z = %.3f m, lowest z = %.3f m\n", simulator.q()[0],
                simulator.q()[1], simulator.q()[2], summary.min_trunk_height);
    if (cli.profile) {
      const PhaseTimes& p = simulator.profile();
      const double total = p.dynamics + p.contact + p.integration + summary.controller_seconds;
      auto line = [&](const char* name, double seconds) {
        std::printf("  %-12s %8.3f s  %6.1f %%  %7.3f us/step\n", name, seconds, 100 * seconds / total,
                    1e6 * seconds / p.steps);
      };
      std::printf("profile (timer overhead included):\n");
      line("dynamics", p.dynamics);
      line("contact", p.contact);
      line("integration", p.integration);
      line("control", summary.controller_seconds);
    }
    if (!summary.finite) {
      std::fprintf(stderr, "rbdc-sim: the state became non-finite at t = %.4f s\n", simulated);
      return 2;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbdc-sim: %s\n", e.what());
    return 1;
  }
}
