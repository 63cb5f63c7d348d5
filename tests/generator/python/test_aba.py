"""Forward dynamics by the articulated-body algorithm (algorithms/aba.py): equal to CRBA + the sparse
LᵀDL factor on a fixed-base tree with oblique axes, a prismatic joint and foot forces, on a chain and
on a floating base (its trunk solved by a 6 × 6 LDLᵀ); `auto` keeps the factor for a short arm and
takes ABA for a long chain, and says so. The emitted code is checked against the runtime (armature
included) by generator_verify_random_aba (tests/generator/CMakeLists.txt)."""

import copy
import os
import unittest

from numeric_check import DATA, evaluate, random_state

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes.schedule import scheduled_function

FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))


def scene(schedule, **keys):
    return scene_from_dict({"name": "x", "quantities": ["forward_dynamics"], "schedule": schedule, **keys})


def chain(links):
    """A fixed-base serial chain of `links` revolute joints about x, y, z in turn, as an IR dict."""
    body = {"com": [0.0, 0.0, 0.05], "inertia_com": [[2e-3, 0, 0], [0, 2e-3, 0], [0, 0, 1e-3]], "mass": 0.5}
    joint = {"lower": None, "upper": None, "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}
    bodies = [dict(body, name="base")] + [dict(body, name="link%d" % i) for i in range(1, links + 1)]
    joints = [dict(joint, name="root", type="fixed", parent=-1, axis=[0, 0, 0], translation=[0, 0, 0],
                   q_index=0, v_index=0)]
    for i in range(1, links + 1):
        joints.append(dict(joint, name="j%d" % i, type="revolute", parent=i - 1,
                           axis=[1.0 if k == i % 3 else 0.0 for k in range(3)], translation=[0, 0, 0.1],
                           q_index=i - 1, v_index=i - 1))
    nb = links + 1
    return load_ir({"format": "rbdc-ir-1", "name": "chain", "nb": nb, "floating_base": False,
                    "gravity": [0, 0, -9.81], "bodies": bodies, "joints": joints, "nq": links,
                    "nv": links, "lambda": [i - 1 for i in range(1, nb)],
                    "feet": [{"name": "tip", "body": links, "offset": [0, 0, 0.1]}],
                    "PRED": [i - 1 for i in range(1, nb)], "SUCC": list(range(1, nb)),
                    "kappa": [[] for _ in range(nb)], "mu": [[] for _ in range(nb)],
                    "nu": [[] for _ in range(nb)]})


class ArticulatedBodyAlgorithm(unittest.TestCase):
    def assert_same_acceleration(self, robot, scene_keys=None):
        keys = scene_keys or {}
        factor = scheduled_function(robot, scene("scalar", **keys), "forward_dynamics")
        aba = scheduled_function(robot, scene("aba", **keys), "forward_dynamics")
        self.assertIn("articulated-body", aba.schedule)
        for seed in range(5):
            state = random_state(robot, len(robot.feet), seed)
            expected, actual = evaluate(factor, state)["a"], evaluate(aba, state)["a"]
            scale = max(1.0, max(abs(x) for x in expected))
            for x, y in zip(actual, expected):
                self.assertLess(abs(x - y), 1e-12 * scale)

    def test_equals_the_factor_on_a_branched_tree_with_a_slider_and_foot_forces(self):
        self.assert_same_acceleration(FIXED)

    def test_equals_the_factor_on_a_chain(self):
        self.assert_same_acceleration(chain(12))

    def test_auto_keeps_the_factor_for_a_short_tree_and_takes_aba_for_a_long_chain(self):
        short = scheduled_function(chain(4), scene("auto"), "forward_dynamics")
        self.assertTrue(short.schedule.startswith("scalar tree"), short.schedule)
        long = scheduled_function(chain(30), scene("auto"), "forward_dynamics")
        self.assertTrue(long.schedule.startswith("articulated-body algorithm"), long.schedule)

    def test_equals_the_factor_on_a_floating_base(self):
        self.assert_same_acceleration(FLOATING)


if __name__ == "__main__":
    unittest.main()
