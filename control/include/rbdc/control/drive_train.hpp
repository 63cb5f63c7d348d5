// The trot robot with or without its drive train (issue 14): rbdc-sim --rotors.
#pragma once

#include <string>

#include "rbdc/actuator_mode.hpp"
#include "rbdc/model.hpp"

namespace rbdc::control {

/// The robot of `urdf` (sim::load_robot: its <name>.topology.yaml). With `mode` Full or Armature, the
/// overlay <name>_rotors.topology.yaml next to it instead (robots/mini_cheetah_rotors.topology.yaml:
/// MIT's twelve rotors), its actuators kept as `mode` asks (rbdc::with_actuator_mode). Throws
/// std::invalid_argument when there is no such overlay, rbdc::ModelError when it does not load.
Model load_trot_robot(const std::string& urdf, ActuatorMode mode);

}  // namespace rbdc::control
