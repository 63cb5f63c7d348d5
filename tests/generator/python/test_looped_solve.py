"""The looped form of forward_dynamics_derivatives (passes/looped_solve.py): its traced terms, solved
by an independent route (M rebuilt from the packed factor, a dense numpy solve), equal the scalar
tree's outputs; the scene's schedule forces it, `auto` picks it by cost and says so, a coupled robot
never gets it. The emitted loop itself is checked against the runtime by `rbdc verify` (arm7 and
humanoid32 `derivatives`, whose `auto` picks it) and compiled under nvcc."""

import os
import unittest

import numpy as np
from mini_cheetah import skip_reason
from numeric_check import DATA, evaluate, random_state
from test_coupling import GRIPPER, load as load_coupled

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph import expr as ex
from rbdcgen.algorithms.forward_dynamics import dof_ancestors
from rbdcgen.passes.schedule import scheduled_function

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
NAME = "forward_dynamics_derivatives"


def scene(schedule):
    return scene_from_dict({"name": "x", "derivatives": [NAME], "schedule": schedule})


def solved_outputs(fn, state):
    """{output: column-major floats}: the looped form's terms, solved densely."""
    solve = fn.solve
    values = iter(ex.evaluate(fn.output_exprs(), state))
    terms = {arg.name: [next(values) if e is not None else 0.0 for e in fn.values[arg.name]]
             for arg in solve.terms}
    nv, columns = solve.nv, solve.columns
    factor = np.eye(nv)  # unit lower triangular, entries at each dof's ancestors
    packed = iter(terms["L"])
    for i in range(nv):
        for j in dof_ancestors(solve.parents, i):
            factor[i, j] = next(packed)
    mass = factor.T @ np.diag(1.0 / np.array(terms["D_inv"])) @ factor
    solution = np.linalg.solve(mass, np.array(terms["rhs"]).reshape(nv, columns))
    outputs, first = {}, 0
    for name, width in solve.blocks:
        outputs[name] = list(solution[:, first:first + width].T.ravel())
        first += width
    return outputs


class LoopedForwardDynamicsDerivatives(unittest.TestCase):
    def test_terms_solved_equal_the_scalar_tree(self):
        for robot in (FLOATING, FIXED):
            looped = scheduled_function(robot, scene("looped_solve"), NAME)
            scalar = scheduled_function(robot, scene("scalar"), NAME)
            self.assertIsNotNone(looped.solve)
            self.assertIsNone(scalar.solve)
            self.assertEqual(looped.schedule, "looped solve, as the scene asks")
            self.assertEqual(looped.outputs, scalar.outputs)
            for seed in (1, 2):
                state = random_state(robot, len(robot.feet), seed)
                want = evaluate(scalar, state)
                got = solved_outputs(looped, state)
                for output, values in want.items():
                    scale = max(1.0, max(abs(x) for x in values))
                    error = max(abs(g - w) for g, w in zip(got[output], values)) / scale
                    self.assertLess(error, 1e-12, (robot.name, output, seed))

    def test_auto_picks_by_cost_and_says_so(self):
        fn = scheduled_function(FLOATING, scene("auto"), NAME)
        self.assertRegex(fn.schedule, r"^(looped solve|scalar tree)\b.*\d+ arithmetic instructions, "
                                      r"(scalar tree|looped solve) \d+$")

    @unittest.skipIf(skip_reason(), skip_reason())
    def test_a_coupled_robot_keeps_the_scalar_tree(self):
        """Its solve is in the independent coordinates (passes/project.py), not over the dof tree."""
        gripper = load_coupled(GRIPPER)
        self.assertTrue(gripper.couplings)
        self.assertIsNone(scheduled_function(gripper, scene("looped_solve"), NAME).solve)


if __name__ == "__main__":
    unittest.main()
