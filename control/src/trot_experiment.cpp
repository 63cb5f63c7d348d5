#include "rbdc/control/trot_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>

#include "rbdc/result_file.hpp"
#include "rbdc/sim/run.hpp"

namespace rbdc::control {
namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr double kFallHeight = 0.12;      // m, trunk origin
constexpr double kFallAngle = 45.0 / kDeg;

void write_trace_header(std::ostream& out) {
  out << "t,x,y,z,vx,roll,pitch,yaw,roll_desired,pitch_desired,pair,attitude_control";
  for (const char* foot : {"LF", "RF", "LH", "RH"})
    out << ',' << foot << "_fx," << foot << "_fy," << foot << "_fz";
  out << '\n';
}

void write_trace_row(std::ostream& out, sim::Simulator& simulator, const ControllerStatus& s) {
  const VectorX& q = simulator.q();
  const VectorX& v = simulator.v();
  const Matrix3 W_R_B = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  const double vx = (W_R_B * v.segment<3>(3)).x();
  out << simulator.time() << ',' << q[0] << ',' << q[1] << ',' << q[2] << ',' << vx << ','
      << kDeg * s.attitude.roll << ',' << kDeg * s.attitude.pitch << ',' << kDeg * s.attitude.yaw << ','
      << kDeg * s.roll_desired.angle << ',' << kDeg * s.pitch_desired.angle << ','
      << (s.pair == StancePair::LfRh ? 0 : 1) << ',' << (s.attitude_control ? 1 : 0);
  for (const sim::FootContact& c : simulator.contacts())
    out << ',' << c.force_W.x() << ',' << c.force_W.y() << ',' << c.force_W.z();
  out << '\n';
}

}  // namespace

void AbsStats::add(double x) {
  sum += std::abs(x);
  max = std::max(max, std::abs(x));
  ++count;
}

ExperimentResult run_trot_experiment(const Model& model, sim::DynamicsModel& dynamics,
                                     const ExperimentOptions& options) {
  sim::Simulator simulator(dynamics, options.sim);
  OscTrotController controller(model, options.trot, options.control, options.sim.contact.foot_radius);
  std::optional<ResultFile> trace;  // the previous trace stays until this run ends
  if (!options.trace_csv.empty()) {
    trace.emplace(options.trace_csv);
    write_trace_header(trace->stream());
  }
  sim::RunOptions run;
  run.duration = options.duration;
  run.control_period = options.control_period;
  run.sample_interval = trace ? 1e-3 : 0;

  ExperimentResult result;
  const long total_steps = std::lround(options.duration / options.sim.dt);
  const long half = total_steps / 2;
  long steps = 0;
  double x_half = 0, t_half = 0;
  sim::RunCallbacks callbacks;
  callbacks.updated = [&](sim::Simulator&) {
    const ControllerStatus& s = controller.status();
    if (!s.attitude_control) return;
    result.roll_error.add(kDeg * (s.attitude.roll - s.roll_desired.angle));
    result.pitch_error.add(kDeg * (s.attitude.pitch - s.pitch_desired.angle));
    result.roll.add(kDeg * s.attitude.roll);
    result.pitch.add(kDeg * s.attitude.pitch);
  };
  // A row per millisecond of a state the controller acted on: none for the final state.
  callbacks.sample = [&](sim::Simulator& s) {
    if (steps < total_steps) write_trace_row(trace->stream(), s, controller.status());
  };
  // After each step: the half-way position for the mean speed, then the fall criteria.
  callbacks.stop = [&](sim::Simulator& s) -> const char* {
    if (++steps == half) x_half = s.q()[0], t_half = s.time();
    const TrunkAttitude attitude = trunk_attitude(s.q().data(), s.v().data());
    if (s.q()[2] < kFallHeight) return "trunk below 0.12 m";
    if (std::abs(attitude.roll) > kFallAngle) return "|roll| > 45 deg";
    if (std::abs(attitude.pitch) > kFallAngle) return "|pitch| > 45 deg";
    return nullptr;
  };
  const sim::RunSummary summary = sim::run(simulator, controller, run, callbacks);
  if (trace) trace->commit();

  result.controller_seconds = summary.controller_seconds;
  result.controller_calls = summary.controller_calls;
  result.simulated = simulator.time();
  if (!summary.finite || summary.stop_reason) {
    result.fell = true;
    result.fall_time = simulator.time();
    result.fall_reason = summary.finite ? summary.stop_reason : "non-finite state";
  } else if (result.simulated > t_half) {
    result.mean_speed = (simulator.q()[0] - x_half) / (result.simulated - t_half);
  }
  return result;
}

}  // namespace rbdc::control
