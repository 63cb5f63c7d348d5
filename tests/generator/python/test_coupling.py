"""Mimic couplings in the generator (rbdcgen/passes/project.py, views/coupled.py): the two-finger gripper of
tests/data/two_finger_gripper.urdf traced and evaluated against the hand calculation of
tests/runtime/test_coupling.cpp, the IR's tree turned into independent coordinates, and the
derivatives of coupled robots against central differences of their primal functions."""

import json
import os
import subprocess
import unittest

from mini_cheetah import ROOT, model_tool, skip_reason
from numeric_check import evaluate as numeric_evaluate, random_state
from test_derivatives import ALL, CASES, TOLERANCE, central_difference, relative_error
from rbdcgen.graph import expr as ex
from rbdcgen.algorithms.forward_dynamics import dof_parents
from rbdcgen.passes import looped_feet_forces
from rbdcgen.passes.looped_rnea_derivatives import has_looped_form
from rbdcgen.views.coupled import tree_view
from rbdcgen.errors import RbdcError
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import Scene
from rbdcgen.passes.trace import trace_function

GRIPPER = os.path.join(ROOT, "tests", "data", "two_finger_gripper.urdf")
MIMIC_CHAIN = os.path.join(ROOT, "tests", "data", "mimic_chain.urdf")
MIMIC_FINGERS = os.path.join(ROOT, "tests", "data", "mimic_fingers.urdf")
MIMIC_ACROSS_BRANCHES = os.path.join(ROOT, "tests", "data", "mimic_across_branches.urdf")


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


@unittest.skipIf(skip_reason(), skip_reason())
class CoupledDerivatives(unittest.TestCase):
    """∂τ' = Gᵀ ∂τ G, ∂ṗ' = ∂ṗ G and the forward-dynamics derivatives in independent coordinates equal central
    differences of the coupled robot's own inverse and forward dynamics (on the manifold for a
    floating base): a chain of two mimics (one with offset and multiplier -3), the gripper and fingers on
    an arm."""

    def check(self, robot):
        state = random_state(robot, len(robot.feet), 5)
        for name in ("inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives",
                     "forward_dynamics_derivatives", "feet_force_term_derivatives", "feet_velocity_derivatives"):
            if name.startswith("feet_") and not robot.feet:
                continue
            got = numeric_evaluate(trace_function(robot, ALL, name), state)
            for output, primal_name, primal_output, wrt in CASES[name]:
                at = dict(state, a=[0.0] * robot.nv) if name == "bias_derivatives" else state
                primal = trace_function(robot, ALL, primal_name)
                want = central_difference(robot, primal, primal_output, at, wrt)
                with self.subTest(robot=robot.name, base=robot.floating_base, output=output):
                    self.assertEqual(len(got[output]), len(want))
                    self.assertLess(relative_error(got[output], want), TOLERANCE)

    def test_mimic_chain(self):
        for base in ("fixed", "floating"):
            self.check(load(MIMIC_CHAIN, base))

    def test_gripper(self):
        for base in ("fixed", "floating"):
            self.check(load(GRIPPER, base))

    def test_fingers_on_an_arm(self):
        """Its M' factorises over a tree of the independent dofs (CoupledDofTree)."""
        for base in ("fixed", "floating"):
            self.check(load(MIMIC_FINGERS, base))


@unittest.skipIf(skip_reason(), skip_reason())
class CoupledDofTree(unittest.TestCase):
    """The independent dofs' tree that M' = Gᵀ M G factorises over (views/coupled.py, dof_parents)."""

    def test_fingers_that_move_together_keep_a_tree(self):
        # shoulder, wrist, the fingers' one dof below the wrist, the other arm's joint at the root
        self.assertEqual(dof_parents(load(MIMIC_FINGERS)), [-1, 0, 1, -1])
        self.assertEqual(dof_parents(load(MIMIC_FINGERS, "floating")), [-1, 0, 1, 2, 3, 4, 5, 6, 7, 5])

    def test_the_rnea_derivatives_loop_on_the_tree(self):
        """passes/looped_rnea_derivatives.py: expanded inputs, entries projected as written."""
        fingers = load(MIMIC_FINGERS)
        self.assertTrue(all(has_looped_form(fingers, name) for name in
                            ("inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives")))
        # the feet's force-term loop too (passes/looped_feet_forces.py): on the tree's 5 dofs, projected
        feet = looped_feet_forces.on_tree(fingers, Scene(name="x"), "out")
        self.assertEqual((len(feet.parents), feet.columns, len(feet.coupling)), (5, 4, 5))
        self.assertIn(", true>(feet_dof_tree", feet.loops()[-1])

    def test_a_coupling_across_branches_factorises_densely(self):
        # a2's dof also moves b2, below b1 (numbered after a2): no tree, every dof the previous one's child
        self.assertEqual(dof_parents(load(MIMIC_ACROSS_BRANCHES)), [-1, 0, 1])


if __name__ == "__main__":
    unittest.main()
