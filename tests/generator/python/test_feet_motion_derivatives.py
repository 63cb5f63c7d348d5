"""The feet's motion derivatives along their paths (rbdcgen/algorithms/feet_motion_derivatives.py)
against an independent route, forward-mode tangents of the traced kinematics (ṗ and J a + J̇v), and
their cost: O(depth) per foot, where the tangents' is O(depth²)."""

import json
import os
import unittest

import mini_cheetah
from numeric_check import DATA, chain, random_state
from rbdcgen.algorithms import feet_motion_derivatives, frames, jacobian, kinematics
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph import expr as ex
from rbdcgen.graph import spatial as sp
from rbdcgen.graph.flops import count_ops
from rbdcgen.passes import differentiate
from rbdcgen.passes.trace import trace_function
from rbdcgen.views.scalar import TracedModel

SCENE = scene_from_dict({"name": "x", "derivatives": ["feet_velocity_derivatives"]})


def by_tangents(m):
    """∂ṗ/∂q, ∂p̈/∂q, ∂p̈/∂v, column-major, by forward-mode tangents of the traced kinematics."""
    pdot = [x for foot in kinematics.feet_velocities(m) for x in foot]
    pddot = [sp.dot(row, m.a) + bias for row, bias in zip(
        jacobian.feet_jacobian(m), [x for foot in frames.feet_bias_accelerations(m) for x in foot])]
    r2 = differentiate.q_and_v(m, pddot, "q", "v")
    return differentiate.q_and_v(m, pdot, "q", "v")["q"] + r2["q"] + r2["v"]


def along_paths(m):
    dq, dv = feet_motion_derivatives.feet_acceleration_derivatives(m, m.feet)
    return sum((differentiate.column_major(rows) for rows in
                (feet_motion_derivatives.feet_velocity_derivatives(m), dq, dv)), ())


class FeetMotionDerivatives(unittest.TestCase):
    def check(self, robot):
        for seed in (1, 2, 3):
            state = random_state(robot, len(robot.feet), seed)
            with ex.Graph():
                m = TracedModel(robot, SCENE)
                want = ex.evaluate(list(by_tangents(m)), state)
                got = ex.evaluate(list(along_paths(m)), state)
            scale = max(1.0, max(abs(x) for x in want))
            with self.subTest(robot=robot.name, floating=robot.floating_base, seed=seed):
                self.assertEqual(len(got), len(want))
                self.assertLess(max(abs(g - w) for g, w in zip(got, want)) / scale, 1e-13)

    def test_equal_the_tangents_floating_and_fixed(self):
        for name in ("tiny_floating.json", "tiny_fixed.json"):
            self.check(load_ir(os.path.join(DATA, name)))
        self.check(chain(7))

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_equal_the_tangents_on_the_mini_cheetah(self):
        for base in ("floating", "fixed"):
            self.check(mini_cheetah.load(base))

    def test_a_foot_on_a_fixed_root_has_zero_derivatives(self):
        data = json.load(open(os.path.join(DATA, "tiny_fixed.json")))
        data["feet"] = data["feet"] + [{"name": "on_root", "body": 0, "offset": [0.1, 0.0, 0.0]}]
        robot = load_ir(data)
        self.check(robot)
        with ex.Graph():
            m = TracedModel(robot, SCENE)
            rows = feet_motion_derivatives.feet_velocity_derivatives(m)[-3:]
            rows += sum(feet_motion_derivatives.feet_acceleration_derivatives(m, m.feet[-1:]), [])
        self.assertTrue(all(x.is_const(0.0) for row in rows for x in row))

    def test_cost_grows_linearly_with_the_depth(self):
        """A chain twice as long: about twice the operations (the tangents' were four times)."""
        short, long = (count_ops(trace_function(chain(n), SCENE, "feet_velocity_derivatives"))["total"]
                       for n in (20, 40))
        self.assertLess(long, 2.3 * short)


if __name__ == "__main__":
    unittest.main()
