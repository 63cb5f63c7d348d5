"""Scenes: what to emit for a robot (docs/generator_core.md, "Scenes").

A scene names the quantities to emit, the gravity, the base, the feet kept and those in contact,
the inputs known to be zero and the joints locked at a value. Zero inputs vanish from the traced
graph and from the signatures; `base` and `locked_joints` are applied by the C++ model builder
(the product passes them to rbdc-model), the rest here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Tuple

import yaml

# Function names of docs/generated_api.md, in emission order.
QUANTITIES = (
    "feet_positions",
    "feet_velocities",
    "feet_jacobian",
    "quadratic_velocity_terms",
    "gravity_terms",
    "bias",
    "feet_force_terms",
    "inverse_dynamics",
    "mass_matrix",
    "mass_matrix_factor",
    "forward_dynamics",
    "osc_open_chain",
    "osc_closed_chain",
)
# Combined functions: several quantities of one use traced as one function (shared kinematics, CSE
# across outputs), and other layouts of a quantity's outputs (M's lower triangle alone), emitted
# after QUANTITIES and only when a scene lists them.
COMBINED = ("step_terms", "mass_matrix_lower")
# The whole-body controller's quantities (issue 21; docs/generated_api.md), emitted after COMBINED
# and only when a scene lists them; the frame ones for the scene's `frames`.
WHOLE_BODY = ("frame_placements", "frame_velocities", "frame_jacobians", "frame_bias_accelerations",
              "feet_bias_accelerations", "center_of_mass", "center_of_mass_jacobian",
              "centroidal_momentum_matrix", "centroidal_bias", "mass_matrix_inverse")
FRAME_QUANTITIES = ("frame_placements", "frame_velocities", "frame_jacobians", "frame_bias_accelerations")
# Functions with the isomorphic limbs in SIMD lanes (passes/lane_functions.py), emitted after those and only
# when a scene lists them.
LANE_QUANTITIES = ("bias_lanes", "inverse_dynamics_lanes", "mass_matrix_lanes", "mass_matrix_lower_lanes",
                   "forward_dynamics_lanes", "osc_open_chain_lanes",
                   "inverse_dynamics_derivatives_lanes", "bias_derivatives_lanes",
                   "gravity_derivatives_lanes", "forward_dynamics_derivatives_lanes")
# Rigid-contact functions for the scene's contact feet (algorithms/contact_dynamics.py), emitted
# after those and only when a scene lists them.
CONTACT_QUANTITIES = ("contact_dynamics", "impulse_dynamics")
FEET_QUANTITIES = ("feet_positions", "feet_velocities", "feet_jacobian", "feet_force_terms",
                   "feet_bias_accelerations",
                   "step_terms")
OSC_QUANTITIES = ("osc_open_chain", "osc_closed_chain", "osc_open_chain_lanes")
ZERO_INPUTS = ("v", "a", "tau", "f")
# Derivative quantities (passes/differentiate.py), emitted after the quantities, in this order.
DERIVATIVES = ("inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives",
               "forward_dynamics_derivatives", "feet_velocity_derivatives",
               "feet_force_term_derivatives", "contact_dynamics_derivatives")
CONTACT_DERIVATIVES = ("contact_dynamics_derivatives",)
FEET_DERIVATIVES = ("feet_velocity_derivatives", "feet_force_term_derivatives")
KEYS = ("name", "quantities", "gravity", "base", "locked_joints", "feet", "frames", "contacts", "zero_inputs",
        "derivatives", "actuators", "schedule", "frame_axes")
# How a quantity is evaluated (passes/schedule.py): `auto` picks the cheapest of the scalar tree, the
# isomorphic limbs in SIMD lanes, a looped solve, the articulated-body algorithm, the looped factor,
# the looped CRBA and the looped RNEA derivatives; the others force one where a function has it.
SCHEDULES = ("auto", "scalar", "limb_lanes", "looped_solve", "aba", "looped_factor", "looped_crba", "looped_rnea", "lanes_looped_rnea", "looped_feet", "looped_osc", "low_rank", "chain_loop")
# How the robot's actuators (docs/model.md, "Actuators") enter the generated code: `full` as the
# runtime models them (rotor bodies and armature), `armature` with each rotor reduced to its
# reflected inertia on M's diagonal, `none` without any (the code of a robot without actuators).
ACTUATOR_MODES = ("full", "armature", "none")
# Which axes the frame functions' outputs are in (docs/generated_api.md, "Frames and centroidal
# quantities"): both (frame_velocities v_local and v_world, frame_jacobians J_local and J_world,
# frame_bias_accelerations spatial and classical), or only the world-aligned or only the local one.
FRAME_AXES = ("both", "world", "local")


class SceneError(ValueError):
    """Bad scene; the message names the file, the key and the problem."""


@dataclass(frozen=True)
class Scene:
    name: str = "full"
    quantities: Optional[Tuple[str, ...]] = None   # None: all that apply to the robot
    gravity: Optional[Tuple[float, float, float]] = None  # None: the robot's (IR) gravity
    base: str = "floating"                          # floating | fixed
    locked_joints: Tuple[Tuple[str, float], ...] = ()  # (joint name, value), sorted by name
    feet: Optional[Tuple[str, ...]] = None          # None: all feet of the robot
    frames: Tuple[str, ...] = ()                    # operational frames the frame_* functions cover
    contacts: Optional[Tuple[str, ...]] = None      # None: all kept feet
    zero_inputs: Tuple[str, ...] = ()
    derivatives: Tuple[str, ...] = ()               # none unless the scene lists them
    actuators: str = "full"                         # full | armature | none (ACTUATOR_MODES)
    schedule: str = "auto"                          # auto | scalar | limb_lanes | looped_solve | aba | looped_factor | looped_crba | looped_rnea | lanes_looped_rnea | looped_feet | looped_osc | low_rank | chain_loop
    frame_axes: str = "both"                        # both | world | local (FRAME_AXES)
    source: str = "<default>"

    # --- resolution against a robot -------------------------------------------------------
    def fail(self, key, problem):
        raise SceneError("%s: %s: %s" % (self.source, key, problem))

    def gravity_for(self, robot):
        return robot.gravity if self.gravity is None else self.gravity

    def feet_for(self, robot):
        """The kept feet, in the robot's order; unknown names are an error."""
        names = [f.name for f in robot.feet]
        if self.feet is None:
            return tuple(robot.feet)
        for name in self.feet:
            if name not in names:
                self.fail("feet", "unknown foot '%s' (the robot has: %s)"
                          % (name, ", ".join(names) or "no feet"))
        return tuple(f for f in robot.feet if f.name in self.feet)

    def frames_for(self, robot):
        """The scene's frames in the scene's order; a name the robot does not have is an error."""
        by_name = {f.name: f for f in robot.frames}
        for name in self.frames:
            if name not in by_name:
                self.fail("frames", "unknown frame '%s' (the robot has: %s)"
                          % (name, ", ".join(by_name) or "no frames"))
        return tuple(by_name[name] for name in self.frames)

    def contacts_for(self, robot):
        """The kept feet in contact (osc_closed_chain and the contact functions), in the robot's order."""
        kept = self.feet_for(robot)
        if self.contacts is None:
            return kept
        kept_names = [f.name for f in kept]
        for name in self.contacts:
            if name not in kept_names:
                self.fail("contacts", "'%s' is not a kept foot (kept: %s)"
                          % (name, ", ".join(kept_names) or "none"))
        return tuple(f for f in kept if f.name in self.contacts)

    def quantities_for(self, robot):
        """The functions to emit: the requested ones, or all of QUANTITIES that apply to this robot.
        OSC functions need a floating base; feet functions need feet; neither OSC nor the combined
        functions are implemented for mimic couplings (docs/model.md)."""
        has_feet = bool(self.feet_for(robot))
        coupled = "mimic couplings: use --lock-mimic or --independent-mimic"

        def refusal(name):
            """Why `name` does not apply to the robot, or None."""
            if name in OSC_QUANTITIES + COMBINED + WHOLE_BODY + CONTACT_QUANTITIES and robot.couplings:
                return coupled
            if name in FRAME_QUANTITIES and not self.frames_for(robot):
                return "the scene lists no frames"
            if name in CONTACT_QUANTITIES:
                return self.contact_refusal(robot)
            if name in OSC_QUANTITIES and not robot.floating_base:
                return "fixed base"
            return None if has_feet or name not in FEET_QUANTITIES else "no feet"

        if self.quantities is None:
            return tuple(q for q in QUANTITIES if refusal(q) is None)
        for name in self.quantities:
            if refusal(name) is not None:
                self.fail("quantities", "'%s' does not apply to robot '%s' (%s)"
                          % (name, robot.name, refusal(name)))
        return tuple(q for q in QUANTITIES + COMBINED + WHOLE_BODY + LANE_QUANTITIES + CONTACT_QUANTITIES
                     if q in self.quantities)

    def contact_refusal(self, robot):
        """Why the contact functions do not apply to the robot and scene, or None: they need a
        non-empty contact set (without contacts they are forward_dynamics) and no mimic couplings."""
        if robot.couplings:
            return "mimic couplings: use --lock-mimic or --independent-mimic"
        if not self.contacts_for(robot):
            return "no contacts: the scene lists none or the robot has no feet (use forward_dynamics)"
        return None

    def derivatives_for(self, robot):
        """The derivative functions to emit, in DERIVATIVES order; feet ones need feet."""
        if not self.feet_for(robot):
            for name in self.derivatives:
                if name in FEET_DERIVATIVES:
                    self.fail("derivatives", "'%s' does not apply to robot '%s' (no feet)"
                              % (name, robot.name))
        for name in self.derivatives:
            if name in CONTACT_DERIVATIVES and self.contact_refusal(robot) is not None:
                self.fail("derivatives", "'%s' does not apply to robot '%s' (%s)"
                          % (name, robot.name, self.contact_refusal(robot)))
        return tuple(d for d in DERIVATIVES if d in self.derivatives)


def default_scene() -> Scene:
    """Everything, with the robot's gravity, floating base and all feet."""
    return Scene()


def _string_list(scene_fail, key, value, allowed=None):
    if not isinstance(value, list) or not all(isinstance(x, str) for x in value):
        scene_fail(key, "expected a list of names, got %r" % (value,))
    if allowed is not None:
        for x in value:
            if x not in allowed:
                scene_fail(key, "unknown name '%s' (allowed: %s)" % (x, ", ".join(allowed)))
    if len(set(value)) != len(value):
        scene_fail(key, "duplicate names")
    return tuple(value)


def _finite_number(x) -> bool:
    """An int or float (not a bool) that is a finite double."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        return False
    try:
        return math.isfinite(x)
    except OverflowError:  # an int beyond the doubles
        return False


def scene_from_dict(data, source="<scene>") -> Scene:
    def fail(key, problem):
        raise SceneError("%s: %s: %s" % (source, key, problem))

    if not isinstance(data, dict):
        fail("top level", "expected a mapping of scene keys")
    for key in data:
        if key not in KEYS:
            fail(key, "unknown key (allowed: %s)" % ", ".join(KEYS))
    if "name" not in data or not isinstance(data["name"], str) or not data["name"].isidentifier():
        fail("name", "required, a C++ identifier (it names the namespace)")
    quantities = None
    if data.get("quantities") is not None:
        quantities = _string_list(fail, "quantities", data["quantities"],
                                  QUANTITIES + COMBINED + WHOLE_BODY + LANE_QUANTITIES + CONTACT_QUANTITIES)
    gravity = None
    if "gravity" in data:
        g = data["gravity"]
        if g is None or g == "none":
            gravity = (0.0, 0.0, 0.0)
        elif isinstance(g, list) and len(g) == 3 and all(_finite_number(x) for x in g):
            gravity = tuple(float(x) for x in g)
        else:
            fail("gravity", "expected [x, y, z] of finite numbers or none, got %r" % (g,))
    base = data.get("base", "floating")
    if base not in ("floating", "fixed"):
        fail("base", "expected floating or fixed, got %r" % (base,))
    locked = data.get("locked_joints") or {}
    if not isinstance(locked, dict) or not all(
            isinstance(k, str) and _finite_number(v) for k, v in locked.items()):
        fail("locked_joints", "expected a mapping joint name → finite value")
    feet = None if data.get("feet") is None else _string_list(fail, "feet", data["feet"])
    frames = _string_list(fail, "frames", data.get("frames") or [])
    contacts = (None if data.get("contacts") is None
                else _string_list(fail, "contacts", data["contacts"]))
    zero = _string_list(fail, "zero_inputs", data.get("zero_inputs") or [], ZERO_INPUTS)
    derivatives = _string_list(fail, "derivatives", data.get("derivatives") or [], DERIVATIVES)
    actuators = _choice(fail, data, "actuators", ACTUATOR_MODES)
    schedule = _choice(fail, data, "schedule", SCHEDULES)
    frame_axes = _choice(fail, data, "frame_axes", FRAME_AXES)
    return Scene(name=data["name"], quantities=quantities, gravity=gravity, base=base,
                 locked_joints=tuple((k, float(v)) for k, v in sorted(locked.items())), feet=feet,
                 frames=frames, contacts=contacts, zero_inputs=tuple(x for x in ZERO_INPUTS if x in zero),
                 derivatives=tuple(d for d in DERIVATIVES if d in derivatives), actuators=actuators,
                 schedule=schedule, frame_axes=frame_axes, source=source)


def _choice(fail, data, key, choices):
    """data[key], one of `choices` (default the first)."""
    value = data.get(key, choices[0])
    if value not in choices:
        fail(key, "expected %s, got %r" % (" | ".join(choices), value))
    return value


def load_scene(path) -> Scene:
    """Reads and validates a scene YAML file."""
    path = str(path)
    try:
        with open(path, encoding="utf-8") as handle:
            data = yaml.safe_load(handle)
    except OSError as err:
        raise SceneError("%s: cannot read: %s" % (path, err.strerror)) from None
    except (yaml.YAMLError, ValueError) as err:  # ValueError: not UTF-8, an integer of 4300+ digits
        raise SceneError("%s: invalid YAML: %s" % (path, err)) from None
    except RecursionError:
        raise SceneError("%s: invalid YAML: nested too deeply" % path) from None
    return scene_from_dict(data, source=path)
