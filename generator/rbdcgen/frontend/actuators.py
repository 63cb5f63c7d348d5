"""The scene key `actuators` (docs/generator_core.md, "Scenes"): how a robot's geared rotors and
armature (docs/model.md, "Actuators") enter the generated code.

    full      as the runtime models them: rotor bodies in the recursions, armature on M's diagonal
    armature  each rotor reduced to its reflected inertia gr²·aᵀ I_rot a, added to the joint's armature
              (Pinocchio's and MuJoCo's model; rbdc::with_actuator_mode(model, Armature) in the runtime)
    none      no actuators: the code of the robot without them
"""
from __future__ import annotations

from dataclasses import replace

from .ir import Actuator


def reflected_inertia(rotor) -> float:
    """S_rotᵀ I_rot S_rot = gr² aᵀ I a: the rotor's inertia about its axis seen at the joint."""
    a, inertia = rotor.axis, rotor.inertia
    axial = sum(a[r] * inertia[r][c] * a[c] for r in range(3) for c in range(3))
    return rotor.gear_ratio * rotor.gear_ratio * axial


def _reduced(actuator, mode):
    if actuator is None or mode == "full":
        return actuator
    if mode == "none":
        return None
    extra = 0.0 if actuator.rotor is None else reflected_inertia(actuator.rotor)
    return Actuator(armature=actuator.armature + extra)


def with_actuator_mode(robot, mode: str):
    """The robot with its actuators as `mode` (full | armature | none) asks."""
    if mode == "full" or not has_actuators(robot):
        return robot
    return replace(robot, joints=tuple(replace(j, actuator=_reduced(j.actuator, mode)) for j in robot.joints))


def has_actuators(robot) -> bool:
    return any(j.actuator is not None for j in robot.joints)
