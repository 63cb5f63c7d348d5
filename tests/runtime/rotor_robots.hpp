// The test robots (test_robots.hpp) with a geared rotor on every joint, shared by the rotor tests.
#pragma once

#include <vector>

#include "rbdc/model_builder.hpp"
#include "test_robots.hpp"

namespace rbdc::test {

// Inertia J about `axis`, Jt across it (axisymmetric, as a rotor must be).
inline Matrix3 rotor_inertia(const Vector3& axis, double J, double Jt) {
  const Matrix3 aa = axis.normalized() * axis.normalized().transpose();
  return J * aa + Jt * (Matrix3::Identity() - aa);
}

// A rotor on every joint, with oblique axes, placements off the joint and rotated frames, plus an
// armature on every other joint: exercises every term of the rotor recursions.
inline Model with_rotors(Model m) {
  std::vector<ActuatorSpec> actuators;
  for (int i = 1; i < m.nb; ++i) {
    ActuatorSpec a;
    a.joint = m.joints[static_cast<size_t>(i)].name;
    a.where = "test";
    a.has_rotor = true;
    a.gear_ratio = 2.0 + 0.7 * i;
    a.rotor_mass = 0.05 + 0.01 * i;
    const Vector3 axis(0.3 * i, 1.0, -0.2 * (i % 3));
    a.rotor_axis = axis;
    a.rotor_inertia = rotor_inertia(axis, 6e-5, 3.3e-5);
    a.rotor_translation = Vector3(0.02 * i, -0.01, 0.03);
    a.rotor_rotation = rpy(0.2 * i, -0.1, 0.3).transpose();
    if (i % 2 == 0) a.armature = 1e-3 * i;
    actuators.push_back(a);
  }
  add_actuators(m, actuators);
  return m;
}

inline std::vector<Model> rotor_robots() {
  std::vector<Model> robots;
  for (const Model& m : all_robots()) robots.push_back(with_rotors(m));
  return robots;
}

}  // namespace rbdc::test
