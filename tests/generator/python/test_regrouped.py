"""Regrouped inertias (views/regrouped.py) on random robots: each moving body keeps only what its
joint moves, and the traced dynamics, centre of mass and centroidal momentum equal those traced with
the bodies' own inertias."""

import unittest
from unittest import mock

from mini_cheetah import skip_reason
from numeric_check import evaluate, max_relative_error, random_state
from rbdcgen.frontend.random_robot import random_urdf
from rbdcgen.frontend.scene import Scene
from rbdcgen.graph.spatial import inertia_at_origin, snap_axis
from rbdcgen.passes.trace import trace_function
from rbdcgen.views import coupled, regrouped
from test_random_properties import load

FUNCTIONS = ("inverse_dynamics", "mass_matrix", "forward_dynamics")
CENTROIDAL = ("center_of_mass", "centroidal_momentum_matrix")  # traced for robots without couplings


def as_given(tree):
    return tuple((b.mass, tuple(b.mass * c for c in b.com), inertia_at_origin(b)) for b in tree.bodies)


def robots():
    for seed in range(4):
        base = "floating" if seed % 2 == 0 else "fixed"
        yield seed, base, load(random_urdf(seed, max_links=8, mimic=seed >= 2), base)


@unittest.skipIf(skip_reason(), skip_reason())
class Regrouping(unittest.TestCase):
    def test_a_moving_body_keeps_no_mass_and_nothing_its_revolute_joint_leaves_in_place(self):
        for seed, _, robot in robots():
            tree = coupled.tree_view(robot)
            for i, (m, h, ibar) in enumerate(regrouped.body_parameters(tree)):
                joint = tree.joints[i]
                if i == 0 or joint.type != "revolute":
                    continue
                with self.subTest(seed=seed, body=i):
                    self.assertEqual(m, 0.0)
                    axis = [k for k, x in enumerate(snap_axis(joint.axis)) if x != 0.0]
                    if len(axis) == 1:
                        self.assertEqual(h[axis[0]], 0.0)
                        self.assertEqual(ibar[(axis[0] + 2) % 3][(axis[0] + 2) % 3], 0.0)

    def test_the_traced_quantities_equal_those_of_the_bodies_own_inertias(self):
        for seed, base, robot in robots():
            scene = Scene(base=base)
            state = dict(random_state(robot, len(robot.feet), seed), f=[0.0] * 3 * len(robot.feet))
            for name in FUNCTIONS + (() if robot.couplings else CENTROIDAL):
                got = evaluate(trace_function(robot, scene, name), state)
                with mock.patch.object(regrouped, "body_parameters", as_given):
                    want = evaluate(trace_function(robot, scene, name), state)
                for output in want:
                    with self.subTest(seed=seed, function=name, output=output):
                        self.assertLess(max_relative_error(got[output], want[output]), 1e-12)


if __name__ == "__main__":
    unittest.main()
