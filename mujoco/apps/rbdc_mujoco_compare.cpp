// rbdc-mujoco-compare: the trot in our simulator and in MuJoCo 2.2 side by side (paper 000
// Section 6.3, Figures 5-6), with the paper's error measures, wall times and figures.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "rbdc/control/command_line.hpp"
#include "rbdc/control/drive_train.hpp"
#include "rbdc/mujoco/mujoco_run.hpp"
#include "rbdc/result_file.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/trajectory_csv.hpp"

using namespace rbdc;
using namespace rbdc::control;
using namespace rbdc::mujoco;
using namespace rbdc::sim;

namespace {

Trajectory run_ours(const Model& model, const CommandLine& cli, double& wall_seconds) {
  std::unique_ptr<DynamicsModel> dynamics = make_runtime_dynamics(model);
  Simulator simulator(*dynamics, cli.sim);
  PdTrotController controller(model, cli.gait, cli.gains, cli.sim.contact.foot_radius);
  Trajectory trajectory;
  RunCallbacks callbacks;
  callbacks.sample = [&](Simulator& s) { trajectory.push_back({s.time(), s.q(), s.v(), s.contacts()}); };
  const RunSummary summary = run(simulator, controller, cli.run, callbacks);
  if (!summary.finite) throw std::runtime_error("our simulation became non-finite");
  wall_seconds = summary.wall_seconds;
  return trajectory;
}

// Speed only: the same trot without sampling, on the generated dynamics.
double time_ours(const Model& model, const CommandLine& cli, std::string& which) {
  std::unique_ptr<DynamicsModel> dynamics = make_generated_dynamics();
  which = dynamics->name();
  Simulator simulator(*dynamics, cli.sim);
  PdTrotController controller(model, cli.gait, cli.gains, cli.sim.contact.foot_radius);
  RunOptions quiet = cli.run;
  quiet.progress = false;
  quiet.sample_interval = 0;
  return run(simulator, controller, quiet).wall_seconds;
}

double time_mujoco(const Model& model, const mjModel* m, const CommandLine& cli) {
  PdTrotController controller(model, cli.gait, cli.gains, cli.sim.contact.foot_radius);
  RunOptions quiet = cli.run;
  quiet.progress = false;
  quiet.sample_interval = 0;
  return run_mujoco(model, m, controller, quiet).wall_seconds;
}

void write_csv(const std::string& path, const Model& model, const Trajectory& run) {
  TrajectoryCsv csv(path, model);
  for (const Sample& s : run) csv.write(s.t, s.q, s.v, s.contacts);
  csv.finish();
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli;
  cli.out = "mujoco_compare";
  try {
    parse_command_line(argc, argv, Program::Compare, cli);
    if (cli.help) {
      CommandLine defaults;
      defaults.out = cli.out;
      std::fputs(usage(Program::Compare, defaults).c_str(), stdout);
      return 0;
    }
    std::filesystem::create_directories(cli.out);
    // --rotors: ours with the drive train asked for, MuJoCo with its best approximation, the armature.
    const ActuatorMode drive_train = parse_actuator_mode(cli.rotors);
    const Model original = load_trot_robot(cli.urdf, drive_train);
    if (drive_train != ActuatorMode::None) cli.timing = false;  // the timed generated code has no rotors

    mjcf::MjcfOptions mj;
    mj.timestep = cli.sim.dt;
    mj.foot_radius = cli.sim.contact.foot_radius;
    mj.ground_normal = cli.sim.ground.normal();
    mj.contact_stiffness = cli.mj_stiffness;
    mj.contact_damping = cli.mj_damping;
    mj.friction = cli.mj_friction;
    const mjcf::MjModelPtr m = mjcf::load_mjmodel(with_actuator_mode(original, ActuatorMode::Armature), mj);
    // MuJoCo balanced the inertias it found inconsistent: simulate exactly its robot on our side.
    Model balanced = original;
    const std::vector<mjcf::InertiaChange> changes = mjcf::adopt_mujoco_inertias(balanced, m.get());

    std::fprintf(stderr, "rbdc-mujoco-compare: %g s, dt = %g s, rotors %s, MuJoCo %s\n", cli.run.duration,
                 cli.sim.dt, cli.rotors.c_str(), mj_versionString());
    double wall_ours_runtime = 0;
    const Trajectory ours = run_ours(cli.balanced_inertia ? balanced : original, cli, wall_ours_runtime);
    PdTrotController mujoco_controller(balanced, cli.gait, cli.gains, cli.sim.contact.foot_radius);
    const MujocoRun theirs = run_mujoco(balanced, m.get(), mujoco_controller, cli.run);
    std::string fastest = "generated";
    const double wall_ours_fast = cli.timing ? time_ours(original, cli, fastest) : 0;
    const double wall_mujoco = cli.timing ? time_mujoco(balanced, m.get(), cli) : 0;

    const int lf = 0;  // left foreleg = foot 0 (LF_foot)
    const ComparisonMetrics metrics = compare_trajectories(ours, theirs.trajectory, lf);
    write_csv(cli.out + "/ours.csv", balanced, ours);
    write_csv(cli.out + "/mujoco.csv", balanced, theirs.trajectory);

    ResultFile table_file(cli.out + "/comparison.md");
    std::ostream& table = table_file.stream();
    table << "# Our simulator vs MuJoCo " << mj_versionString() << " (" << cli.run.duration
          << " s trot, dt " << cli.sim.dt << " s)\n\n"
          << "| measure | ours vs MuJoCo | paper 000 |\n|---|---|---|\n";
    char line[256];
    std::snprintf(line, sizeof line, "| trunk position MAE x, y, z (mm) | %.1f, %.1f, %.1f | 63, 17, 4.6 |\n",
                  metrics.position_mae_mm.x(), metrics.position_mae_mm.y(), metrics.position_mae_mm.z());
    table << line;
    std::snprintf(line, sizeof line, "| trunk roll, pitch, yaw MAE (deg) | %.2f, %.2f, %.2f | 1.5, 1.3, 2.7 |\n",
                  metrics.euler_mae_deg.x(), metrics.euler_mae_deg.y(), metrics.euler_mae_deg.z());
    table << line;
    std::snprintf(line, sizeof line, "| LF contact activation agreement | %.1f %% | \"very similar\" |\n",
                  100 * metrics.contact_agreement);
    table << line;
    std::snprintf(line, sizeof line, "| LF touch-downs (ours / MuJoCo), mean shift | %d / %d, %.1f ms | - |\n",
                  metrics.touchdowns_ours, metrics.touchdowns_mujoco, metrics.touchdown_shift_ms);
    table << line;
    std::snprintf(line, sizeof line, "| LF vertical contact force MAE (N) | %.2f | 5.65 |\n", metrics.normal_force_mae);
    table << line;
    std::snprintf(line, sizeof line,
                  "| wall time, ours (%s dynamics, no sampling) | %.3f s | 300 s |\n", fastest.c_str(), wall_ours_fast);
    table << line;
    std::snprintf(line, sizeof line, "| wall time, ours (runtime dynamics, balanced inertias, sampled) | %.3f s | - |\n",
                  wall_ours_runtime);
    table << line;
    std::snprintf(line, sizeof line, "| wall time, MuJoCo (implicit, same controller) | %.3f s | 20 s |\n", wall_mujoco);
    table << line;
    std::snprintf(line, sizeof line, "| speed-up ours (%s) over MuJoCo | %.1fx | 0.07x |\n", fastest.c_str(),
                  wall_mujoco / wall_ours_fast);
    table << line;
    table << "\nInertias MuJoCo changed (balanceinertia), used on both sides:\n\n";
    for (const mjcf::InertiaChange& c : changes) {
      std::snprintf(line, sizeof line, "- %s: %.1f %% (Frobenius), diagonal now %.0f, %.0f, %.0f e-6 kg m^2\n",
                    c.body.c_str(), 100 * c.relative_change, 1e6 * c.after(0, 0), 1e6 * c.after(1, 1),
                    1e6 * c.after(2, 2));
      table << line;
    }
    table_file.commit();

    ResultFile summary_file(cli.out + "/comparison_summary.csv");
    std::ostream& summary = summary_file.stream();
    summary << "measure,value\n"
            << "pos_mae_x_mm," << metrics.position_mae_mm.x() << "\npos_mae_y_mm," << metrics.position_mae_mm.y()
            << "\npos_mae_z_mm," << metrics.position_mae_mm.z() << "\nroll_mae_deg," << metrics.euler_mae_deg.x()
            << "\npitch_mae_deg," << metrics.euler_mae_deg.y() << "\nyaw_mae_deg," << metrics.euler_mae_deg.z()
            << "\nlf_contact_agreement," << metrics.contact_agreement << "\nlf_touchdowns_ours,"
            << metrics.touchdowns_ours << "\nlf_touchdowns_mujoco," << metrics.touchdowns_mujoco
            << "\nlf_touchdown_shift_ms," << metrics.touchdown_shift_ms << "\nlf_normal_force_mae_n,"
            << metrics.normal_force_mae << "\nwall_ours_" << fastest << "_s," << wall_ours_fast
            << "\nwall_ours_runtime_sampled_s," << wall_ours_runtime << "\nwall_mujoco_s," << wall_mujoco << "\n";
    summary_file.commit();

    std::ifstream shown(cli.out + "/comparison.md");
    std::printf("%s", std::string(std::istreambuf_iterator<char>(shown), {}).c_str());
    if (cli.plots) {
      const std::string command = "/usr/bin/python3 \"" RBDC_SOURCE_DIR "/mujoco/plot_compare.py\" \"" + cli.out + "\"";
      if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "rbdc-mujoco-compare: plotting failed (%s)\n", command.c_str());
        return 3;
      }
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbdc-mujoco-compare: %s\n", e.what());
    return 1;
  }
}
