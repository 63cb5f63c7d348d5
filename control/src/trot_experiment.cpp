#include "rbdc/control/trot_experiment.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace rbdc::control {
namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr double kFallHeight = 0.12;      // m, trunk origin
constexpr double kFallAngle = 45.0 / kDeg;

FeetForces measured_forces(sim::Simulator& simulator) {
  FeetForces f;
  const std::vector<sim::FootContact>& contacts = simulator.contacts();
  for (int k = 0; k < kFeet; ++k) f.col(k) = contacts[k].force_W;
  return f;
}

void write_trace_header(std::ofstream& out) {
  out << "t,x,y,z,vx,roll,pitch,yaw,roll_desired,pitch_desired,pair,attitude_control";
  for (const char* foot : {"LF", "RF", "LH", "RH"})
    out << ',' << foot << "_fx," << foot << "_fy," << foot << "_fz";
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
  using Clock = std::chrono::steady_clock;
  sim::Simulator simulator(dynamics, options.sim);
  TrotController controller(model, options.trot, options.control, options.sim.contact.foot_radius);
  simulator.reset(controller.standing_configuration(), VectorX::Zero(kNv));
  std::ofstream trace;
  if (!options.trace_csv.empty()) {
    trace.open(options.trace_csv);
    if (!trace) throw std::runtime_error("cannot write the trace '" + options.trace_csv + "'");
    write_trace_header(trace);
  }
  const double dt = options.sim.dt;
  const long steps = std::lround(options.duration / dt);
  const long control_every = std::max(1L, std::lround(options.control_period / dt));
  const long trace_every = std::max(1L, std::lround(1e-3 / dt));
  const long half = steps / 2;
  double x_half = 0, t_half = 0;
  ExperimentResult result;
  JointTorques tau = JointTorques::Zero();
  for (long n = 0; n < steps; ++n) {
    const VectorX& q = simulator.q();
    const VectorX& v = simulator.v();
    if (n % control_every == 0) {
      const FeetForces f = measured_forces(simulator);
      const Clock::time_point start = Clock::now();
      tau = controller.update(simulator.time(), q.data(), v.data(), f);
      result.controller_seconds += std::chrono::duration<double>(Clock::now() - start).count();
      ++result.controller_calls;
      const ControllerStatus& s = controller.status();
      if (s.attitude_control) {
        result.roll_error.add(kDeg * (s.attitude.roll - s.roll_desired.angle));
        result.pitch_error.add(kDeg * (s.attitude.pitch - s.pitch_desired.angle));
        result.roll.add(kDeg * s.attitude.roll);
        result.pitch.add(kDeg * s.attitude.pitch);
      }
    }
    if (trace.is_open() && n % trace_every == 0) {
      const ControllerStatus& s = controller.status();
      const Matrix3 W_R_B = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
      const double vx = (W_R_B * v.segment<3>(3)).x();
      trace << simulator.time() << ',' << q[0] << ',' << q[1] << ',' << q[2] << ',' << vx << ','
            << kDeg * s.attitude.roll << ',' << kDeg * s.attitude.pitch << ',' << kDeg * s.attitude.yaw
            << ',' << kDeg * s.roll_desired.angle << ',' << kDeg * s.pitch_desired.angle << ','
            << (s.pair == StancePair::LfRh ? 0 : 1) << ',' << (s.attitude_control ? 1 : 0);
      const FeetForces f = measured_forces(simulator);
      for (int k = 0; k < kFeet; ++k) trace << ',' << f(0, k) << ',' << f(1, k) << ',' << f(2, k);
      trace << '\n';
    }
    if (n == half) x_half = q[0], t_half = simulator.time();
    simulator.step(tau);
    const VectorX& q_next = simulator.q();
    const TrunkAttitude attitude = trunk_attitude(q_next.data(), simulator.v().data());
    const char* reason = nullptr;
    if (!q_next.allFinite() || !simulator.v().allFinite()) reason = "non-finite state";
    else if (q_next[2] < kFallHeight) reason = "trunk below 0.12 m";
    else if (std::abs(attitude.roll) > kFallAngle) reason = "|roll| > 45 deg";
    else if (std::abs(attitude.pitch) > kFallAngle) reason = "|pitch| > 45 deg";
    if (reason) {
      result.fell = true;
      result.fall_time = simulator.time();
      result.fall_reason = reason;
      break;
    }
  }
  result.simulated = simulator.time();
  if (!result.fell && result.simulated > t_half)
    result.mean_speed = (simulator.q()[0] - x_half) / (result.simulated - t_half);
  return result;
}

}  // namespace rbdc::control
