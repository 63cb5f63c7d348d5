"""Regrouped inertias (views/regrouped.py): arm7's moving bodies keep only what their joints move; on
random robots the traced dynamics, centre of mass and centroidal momentum equal those traced with the
bodies' own inertias, in no more operations."""

import os
import unittest
from unittest import mock

import mini_cheetah
from mini_cheetah import skip_reason
from numeric_check import assert_agree, evaluate, random_state
from rbdcgen.frontend.random_robot import random_urdf
from rbdcgen.frontend.scene import Scene
from rbdcgen.graph.flops import count_ops
from rbdcgen.graph.spatial import inertia_at_origin, snap_axis
from rbdcgen.passes.trace import trace_function
from rbdcgen.views import regrouped
from test_random_properties import load

ARM7 = os.path.join(mini_cheetah.ROOT, "robots", "arm7.urdf")
FUNCTIONS = ("inverse_dynamics", "mass_matrix", "forward_dynamics")
CENTROIDAL = ("center_of_mass", "centroidal_momentum_matrix")  # traced for robots without couplings


def as_given(tree):
    return tuple((b.mass, tuple(b.mass * c for c in b.com), inertia_at_origin(b)) for b in tree.bodies)


def operations(robot, parameters=None):
    """inverse_dynamics' operations, with `parameters` (tree → bodies' parameters) instead of the
    regrouping's if given."""
    if parameters is None:
        return count_ops(trace_function(robot, Scene(), "inverse_dynamics"))["total"]
    with mock.patch.object(regrouped, "body_parameters", parameters):
        return count_ops(trace_function(robot, Scene(), "inverse_dynamics"))["total"]


def robots():
    for seed in range(4):
        base = "floating" if seed % 2 == 0 else "fixed"
        yield seed, base, load(random_urdf(seed, max_links=8, mimic=seed >= 2), base)


@unittest.skipIf(skip_reason(), skip_reason())
class Regrouping(unittest.TestCase):
    def test_arm7s_moving_bodies_keep_no_mass_and_its_inverse_dynamics_loses_a_quarter(self):
        robot = mini_cheetah.load("fixed", ARM7)
        for i, (m, h, ibar) in enumerate(regrouped.body_parameters(robot)[1:], start=1):
            k = [c for c, x in enumerate(snap_axis(robot.joints[i].axis)) if x != 0.0][0]
            self.assertEqual((m, h[k], ibar[(k + 2) % 3][(k + 2) % 3]), (0.0, 0.0, 0.0), robot.bodies[i].name)
        self.assertLess(operations(robot), 0.75 * operations(robot, as_given))

    def test_no_robot_traces_to_more_operations_than_with_its_bodies_own_inertias(self):
        for seed, base, robot in robots():
            with self.subTest(seed=seed):
                self.assertLessEqual(operations(robot), operations(robot, as_given))

    def test_the_traced_quantities_equal_those_of_the_bodies_own_inertias(self):
        for seed, base, robot in robots():
            scene = Scene(base=base)
            state = dict(random_state(robot, len(robot.feet), seed), f=[0.0] * 3 * len(robot.feet))
            for name in FUNCTIONS + (() if robot.couplings else CENTROIDAL):
                got = evaluate(trace_function(robot, scene, name), state)
                with mock.patch.object(regrouped, "body_parameters", as_given):
                    want = evaluate(trace_function(robot, scene, name), state)
                assert_agree(self, got, want, seed=seed, function=name)


if __name__ == "__main__":
    unittest.main()
