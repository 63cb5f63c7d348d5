"""The scene key `actuators` (rbdcgen/actuators.py): `armature` reduces each rotor to its reflected
inertia on M's diagonal, `none` removes the actuators, `full` keeps the rotor bodies; checked on the
traced functions evaluated numerically (generated vs runtime is `rbdc verify`'s job)."""

import os
import re
import unittest
from dataclasses import replace

from numeric_check import DATA, evaluate, random_state

from rbdcgen.frontend.actuators import reflected_inertia, with_actuator_mode
from rbdcgen.frontend.ir import Actuator, Rotor, load_ir
from rbdcgen.frontend.scene import SceneError, scene_from_dict
from rbdcgen.passes.trace import trace_function


def with_actuators(robot):
    """A rotor on every joint (oblique axis, placement off the joint), armature on the odd ones."""
    joints = list(robot.joints)
    for i in range(1, robot.nb):
        a = (0.6, 0.0, 0.8)
        J, Jt = 6e-5, 3e-5
        inertia = tuple(tuple(J * a[r] * a[c] + Jt * ((r == c) - a[r] * a[c]) for c in range(3)) for r in range(3))
        rotor = Rotor(gear_ratio=3.0 + i, mass=0.1, inertia=inertia,
                      rotation=((0.0, -1.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
                      translation=(0.01 * i, 0.02, -0.03), axis=a)
        joints[i] = replace(joints[i], actuator=Actuator(armature=0.01 * (i % 2), rotor=rotor))
    return replace(robot, joints=tuple(joints))


class ActuatorModes(unittest.TestCase):
    def setUp(self):
        self.robot = with_actuators(load_ir(os.path.join(DATA, "tiny_floating.json")))
        self.diagonal = {j.v_index: j.actuator.armature + reflected_inertia(j.actuator.rotor)
                         for j in self.robot.joints[1:]}

    def traced(self, mode, name, output):
        robot = with_actuator_mode(self.robot, mode)
        scene = scene_from_dict({"name": "s", "actuators": mode})
        state = random_state(robot, len(robot.feet), 5)
        return evaluate(trace_function(robot, scene, name), state)[output], state

    def test_armature_is_none_plus_the_reflected_inertia_on_the_diagonal(self):
        M_none, _ = self.traced("none", "mass_matrix", "M")
        M_armature, _ = self.traced("armature", "mass_matrix", "M")
        nv = self.robot.nv
        for r in range(nv):
            for c in range(nv):
                extra = self.diagonal.get(r, 0.0) if r == c else 0.0
                self.assertAlmostEqual(M_armature[c * nv + r], M_none[c * nv + r] + extra, delta=1e-14)
        tau_none, state = self.traced("none", "inverse_dynamics", "tau")
        tau_armature, _ = self.traced("armature", "inverse_dynamics", "tau")
        for k in range(nv):
            self.assertAlmostEqual(tau_armature[k], tau_none[k] + self.diagonal.get(k, 0.0) * state["a"][k],
                                   delta=1e-12)

    def test_full_keeps_the_rotor_bodies(self):
        M_full, _ = self.traced("full", "mass_matrix", "M")
        M_armature, _ = self.traced("armature", "mass_matrix", "M")
        self.assertGreater(max(abs(x - y) for x, y in zip(M_full, M_armature)), 1e-3)  # rotor masses
        c_full, _ = self.traced("full", "quadratic_velocity_terms", "c")
        c_none, _ = self.traced("none", "quadratic_velocity_terms", "c")
        self.assertGreater(max(abs(x - y) for x, y in zip(c_full, c_none)), 1e-6)    # gyroscopic terms

    def test_modes_change_the_robot(self):
        self.assertIs(with_actuator_mode(self.robot, "full"), self.robot)
        self.assertTrue(all(j.actuator is None for j in with_actuator_mode(self.robot, "none").joints))
        reduced = with_actuator_mode(self.robot, "armature")
        self.assertTrue(all(j.actuator.rotor is None for j in reduced.joints[1:]))
        self.assertAlmostEqual(reflected_inertia(self.robot.joints[1].actuator.rotor), 16 * 6e-5, delta=1e-18)

    def test_scene_key(self):
        self.assertEqual(scene_from_dict({"name": "s"}).actuators, "full")
        with self.assertRaisesRegex(SceneError, re.escape("actuators: expected full | armature | none, got 'rotors'")):
            scene_from_dict({"name": "s", "actuators": "rotors"})


if __name__ == "__main__":
    unittest.main()
