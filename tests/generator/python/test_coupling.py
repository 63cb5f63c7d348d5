"""Mimic couplings in the generator (rbdcgen/coupling.py): the two-finger gripper of
tests/data/two_finger_gripper.urdf traced and evaluated against the hand calculation of
tests/runtime/test_coupling.cpp, and the IR's tree turned into independent coordinates."""

import json
import os
import subprocess
import unittest

from mini_cheetah import ROOT, model_tool, skip_reason
from rbdcgen import expr as ex
from rbdcgen.coupling import tree_view
from rbdcgen.errors import RbdcError
from rbdcgen.ir import load_ir
from rbdcgen.scene import Scene
from rbdcgen.trace import trace_function

GRIPPER = os.path.join(ROOT, "tests", "data", "two_finger_gripper.urdf")


def load(path, base="fixed"):
    result = subprocess.run([model_tool(), path, "--%s-base" % base], capture_output=True, text=True,
                            check=True)
    return load_ir(json.loads(result.stdout))


def evaluate(function, **inputs):
    """{output name: its numeric entries} of a traced function at the given inputs."""
    return {name: ex.evaluate(list(values), inputs) for name, values in function.values.items()}


@unittest.skipIf(skip_reason(), skip_reason())
class TwoFingerGripper(unittest.TestCase):
    """y_left = 0.05 + q (0.1 kg), y_right = -(0.05 + 2 q + 0.01) (0.2 kg), gravity 9.81 along -y:
    M' = 0.1 + 4 · 0.2 = 0.9, g' = 9.81 (0.1 - 2 · 0.2) = -2.943, a = (τ - g') / M'."""

    @classmethod
    def setUpClass(cls):
        cls.robot = load(GRIPPER)
        cls.scene = Scene(base="fixed", gravity=(0.0, -9.81, 0.0))

    def trace(self, name):
        return trace_function(self.robot, self.scene, name)

    def test_independent_coordinates(self):
        self.assertEqual((self.robot.nq, self.robot.nv, self.robot.n_joints), (1, 1, 1))
        self.assertEqual([j.q_index for j in self.robot.joints[1:]], [0, 0])  # the follower's is its leader's
        tree = tree_view(self.robot)
        self.assertEqual((tree.nq, tree.nv, tree.n_joints), (2, 2, 2))

    def test_hand_calculation(self):
        self.assertAlmostEqual(evaluate(self.trace("mass_matrix"), q=[0.02])["M"][0], 0.9, places=14)
        self.assertAlmostEqual(evaluate(self.trace("gravity_terms"), q=[0.02])["g"][0], -2.943, places=12)
        p = evaluate(self.trace("feet_positions"), q=[0.02])["p"]
        for got, want in zip(p, [0, 0.07, 0, 0, -0.10, 0]):
            self.assertAlmostEqual(got, want, places=15)
        a = evaluate(self.trace("forward_dynamics"), q=[0.02], v=[0.3], tau=[1.0], f=[0.0] * 6)["a"][0]
        self.assertAlmostEqual(a, (1 + 2.943) / 0.9, places=12)
        c = evaluate(self.trace("quadratic_velocity_terms"), q=[0.02], v=[0.3])["c"][0]
        self.assertEqual(c, 0.0)

    def test_multiplier_and_offset_fold_into_constants(self):
        M = self.trace("mass_matrix")
        self.assertEqual([e.op for e in M.output_exprs()], ["const"])

    def test_functions_without_a_projection_are_refused(self):
        with self.assertRaisesRegex(RbdcError, "osc_open_chain is not supported with mimic couplings"):
            trace_function(load(GRIPPER, "floating"), Scene(base="floating"), "osc_open_chain")


if __name__ == "__main__":
    unittest.main()
