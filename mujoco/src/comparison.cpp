#include "rbdc/mujoco/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rbdc/sim/orientation.hpp"

namespace rbdc::mujoco {
namespace {

Vector3 roll_pitch_yaw(const VectorX& q) {
  const Vector3 xi = sim::zyx_from_rotation(sim::rotation_from_quaternion(q.segment<4>(3)));
  return {xi[2], xi[1], xi[0]};
}

double wrapped(double angle) { return std::remainder(angle, 2 * M_PI); }

std::vector<double> touchdowns(const Trajectory& run, int foot, int n) {
  std::vector<double> times;
  for (int i = 1; i < n; ++i)
    if (run[i].contacts[foot].active && !run[i - 1].contacts[foot].active) times.push_back(run[i].t);
  return times;
}

}  // namespace

ComparisonMetrics compare_trajectories(const Trajectory& ours, const Trajectory& mujoco, int foot) {
  const int n = static_cast<int>(std::min(ours.size(), mujoco.size()));
  if (n == 0) throw std::invalid_argument("compare_trajectories: empty run");
  ComparisonMetrics m;
  m.samples = n;
  int equal = 0;
  for (int i = 0; i < n; ++i) {
    const Sample& a = ours[i];
    const Sample& b = mujoco[i];
    m.position_mae_mm += 1e3 * (a.q.head<3>() - b.q.head<3>()).cwiseAbs();
    const Vector3 d = roll_pitch_yaw(a.q) - roll_pitch_yaw(b.q);
    m.euler_mae_deg += Vector3(std::abs(wrapped(d.x())), std::abs(wrapped(d.y())), std::abs(wrapped(d.z()))) *
                       (180 / M_PI);
    equal += a.contacts[foot].active == b.contacts[foot].active;
    m.normal_force_mae += std::abs(a.contacts[foot].force_W.z() - b.contacts[foot].force_W.z());
  }
  m.position_mae_mm /= n;
  m.euler_mae_deg /= n;
  m.normal_force_mae /= n;
  m.contact_agreement = static_cast<double>(equal) / n;
  const std::vector<double> t_ours = touchdowns(ours, foot, n), t_mujoco = touchdowns(mujoco, foot, n);
  m.touchdowns_ours = static_cast<int>(t_ours.size());
  m.touchdowns_mujoco = static_cast<int>(t_mujoco.size());
  if (!t_ours.empty() && !t_mujoco.empty()) {
    double total = 0;
    for (double t : t_ours) {
      double nearest = INFINITY;
      for (double s : t_mujoco) nearest = std::min(nearest, std::abs(t - s));
      total += nearest;
    }
    m.touchdown_shift_ms = 1e3 * total / t_ours.size();
  }
  return m;
}

}  // namespace rbdc::mujoco
