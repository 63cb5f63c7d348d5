#include "rbdc_bench/random_states.hpp"

#include <cmath>
#include <random>

namespace rbdc_bench {

namespace {

constexpr double kPi = 3.14159265358979323846;

class Sampler {
 public:
  explicit Sampler(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  double symmetric(double bound) { return uniform(-bound, bound); }
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(engine_); }

 private:
  std::mt19937_64 engine_;
};

double joint_angle(const rbdc::Joint& joint, Sampler& sampler, bool within_limits) {
  if (within_limits && std::isfinite(joint.lower) && std::isfinite(joint.upper))
    return sampler.uniform(joint.lower, joint.upper);
  return sampler.symmetric(kPi);
}

}  // namespace

std::vector<State> random_states(const rbdc::Model& model, int count, std::uint64_t seed,
                                 const StateRanges& ranges) {
  Sampler sampler(seed);
  const int n_joints = model.num_joints();
  const Eigen::Index n_feet = static_cast<Eigen::Index>(model.feet.size());
  std::vector<State> states(static_cast<size_t>(count));
  for (State& s : states) {
    s.q.resize(model.nq);
    s.v.resize(model.nv);
    s.a.resize(model.nv);
    s.tau.resize(n_joints);
    s.f.resize(3, n_feet);
    const int root_dofs = model.root_dofs();
    if (model.floating_base) {
      for (int i = 0; i < 3; ++i) s.q[i] = sampler.symmetric(1.0);
      // A normalised 4-D Gaussian is uniform on the unit sphere, i.e. a uniform rotation.
      Eigen::Vector4d quaternion(sampler.normal(), sampler.normal(), sampler.normal(), sampler.normal());
      s.q.segment<4>(3) = quaternion.normalized();
      for (int i = 0; i < root_dofs; ++i) s.v[i] = sampler.symmetric(ranges.trunk_velocity);
    }
    for (int i = 1; i < model.nb; ++i) {
      const rbdc::Joint& joint = model.joints[static_cast<size_t>(i)];
      s.q[joint.q_index] =
          ranges.joint_ranges.empty()
              ? joint_angle(joint, sampler, ranges.within_joint_limits)
              : sampler.uniform(ranges.joint_ranges.at(static_cast<size_t>(i - 1)).first,
                                ranges.joint_ranges.at(static_cast<size_t>(i - 1)).second);
      s.v[joint.v_index] = sampler.symmetric(ranges.joint_velocity);
    }
    for (Eigen::Index i = 0; i < model.nv; ++i) s.a[i] = sampler.symmetric(ranges.acceleration);
    for (Eigen::Index i = 0; i < n_joints; ++i) s.tau[i] = sampler.symmetric(ranges.torque);
    for (Eigen::Index k = 0; k < n_feet; ++k)
      s.f.col(k) = rbdc::Vector3(sampler.symmetric(0.3 * ranges.foot_force),
                                 sampler.symmetric(0.3 * ranges.foot_force),
                                 sampler.uniform(0.0, ranges.foot_force));
  }
  return states;
}

}  // namespace rbdc_bench
