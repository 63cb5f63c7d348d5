#include "rbdc/actuator_mode.hpp"

#include <stdexcept>

#include "rbdc/mass_matrix_rank.hpp"

namespace rbdc {

ActuatorMode parse_actuator_mode(const std::string& text) {
  if (text == "full") return ActuatorMode::Full;
  if (text == "armature") return ActuatorMode::Armature;
  if (text == "none") return ActuatorMode::None;
  throw std::invalid_argument("actuator mode '" + text + "': expected full, armature or none");
}

double reflected_inertia(const Rotor& rotor) {
  return rotor.gear_ratio * rotor.gear_ratio * rotor.axis.dot(rotor.inertia * rotor.axis);
}

Model with_actuator_mode(Model model, ActuatorMode mode) {
  if (mode == ActuatorMode::Full) return model;
  model.has_armature = false;
  for (Joint& joint : model.joints) {
    if (mode == ActuatorMode::None) {
      joint.armature = 0;
    } else if (joint.rotor.gear_ratio > 0) {
      joint.armature += reflected_inertia(joint.rotor);
    }
    joint.rotor = Rotor{};
    model.has_armature = model.has_armature || joint.armature > 0;
  }
  model.has_rotors = false;
  model.X_rotor.clear();
  model.rotor_inertia.clear();
  model.rotor_subspace.clear();
  model.singular_mass_matrix = mass_matrix_singularity(model);  // the actuators may have regularised M
  return model;
}

}  // namespace rbdc
