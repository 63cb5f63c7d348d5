// How much of the drive train a model keeps (docs/model.md, "Actuators"): the scene key `actuators`
// of generated code, and the simulator's --rotors, on the runtime side.
#pragma once

#include <string>

#include "rbdc/model.hpp"

namespace rbdc {

/// Full: rotors as bodies and armature, as loaded. Armature: each rotor reduced to its reflected
/// inertia (added to the joint's armature, M's diagonal only: Pinocchio's and MuJoCo's model).
/// None: neither.
enum class ActuatorMode { Full, Armature, None };

/// "full" | "armature" | "none"; anything else throws std::invalid_argument naming the value.
ActuatorMode parse_actuator_mode(const std::string& text);

/// S_rotᵀ I_rot S_rot = gr² aᵀ I a: the rotor's inertia about its spin axis seen at the joint.
double reflected_inertia(const Rotor& rotor);

/// The model with its actuators as `mode` asks (Full returns it unchanged).
Model with_actuator_mode(Model model, ActuatorMode mode);

}  // namespace rbdc
