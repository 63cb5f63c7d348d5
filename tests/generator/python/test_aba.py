"""Forward dynamics by the articulated-body algorithm (algorithms/aba.py): equal to CRBA + the sparse
LᵀDL factor on a fixed-base tree with oblique axes, a prismatic joint and foot forces, on a chain and
on a floating base (its trunk solved by a 6 × 6 LDLᵀ); `auto` keeps the factor for a short arm and
takes ABA for a long chain, and says so. The emitted code is checked against the runtime (armature
included) by generator_verify_random_aba (tests/generator/CMakeLists.txt)."""

import os
import unittest
from dataclasses import replace
from unittest import mock

from numeric_check import DATA, chain, evaluate, random_state

from rbdcgen.frontend.ir import Actuator, load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph.flops import generic_ops
from rbdcgen.passes import chain_loop, schedule
from rbdcgen.passes.schedule import scheduled_function

FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))


def scene(schedule, **keys):
    return scene_from_dict({"name": "x", "quantities": ["forward_dynamics"], "schedule": schedule, **keys})


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

    def test_equals_the_factor_with_armature_on_some_joints(self):
        """Iᵃ's row and column along S = ±e_k are zero only without armature (aba.py): a chain with
        axis-aligned joints, armature on every other one."""
        robot = chain(8)
        joints = list(robot.joints)
        for i in range(1, len(joints), 2):
            joints[i] = replace(joints[i], actuator=Actuator(armature=0.05, rotor=None))
        self.assert_same_acceleration(replace(robot, joints=tuple(joints)))

    def test_auto_keeps_the_factor_for_a_short_tree_and_takes_aba_for_a_long_chain(self):
        """A long fixed-base chain takes one loop along it (passes/chain_loop.py; measured 30 % faster
        than the straight-line ABA on 30 links); without that form, ABA over the factor."""
        short = scheduled_function(chain(4), scene("auto"), "forward_dynamics")
        self.assertTrue(short.schedule.startswith("scalar tree"), short.schedule)
        looped = scheduled_function(chain(30), scene("auto"), "forward_dynamics")
        self.assertTrue(looped.schedule.startswith("one loop along the chain"), looped.schedule)
        with mock.patch.object(chain_loop, "has_looped_form", lambda robot, name: False):
            long = scheduled_function(chain(30), scene("auto"), "forward_dynamics")
        self.assertTrue(long.schedule.startswith("articulated-body algorithm"), long.schedule)
        # counted as forward dynamics: `rbdc flops` compares it with the runtime's (it raised on ABA)
        self.assertEqual(long.computes, "forward_dynamics")
        self.assertGreater(generic_ops(chain(30), scene("auto"), long.computes)["total"], 0)

    def test_auto_weighs_the_critical_path(self):
        """On a 10-link chain ABA has fewer instructions than the factor (2 129 against 2 176) on twice
        its critical path (474 cycles against 245): by instructions alone `auto` would take ABA; with
        the path weighed (schedule.LATENCY_WEIGHT) it keeps the factor, as Panda's measured faster
        (245 → 197 ns, docs/performance.md, "Forms chosen by their critical path too")."""
        weighed = scheduled_function(chain(10), scene("auto"), "forward_dynamics")
        self.assertTrue(weighed.schedule.startswith("scalar tree"), weighed.schedule)
        with mock.patch.object(schedule, "LATENCY_WEIGHT", 0):
            counted = scheduled_function(chain(10), scene("auto"), "forward_dynamics")
        self.assertTrue(counted.schedule.startswith("articulated-body algorithm"), counted.schedule)

    def test_equals_the_factor_on_a_floating_base(self):
        self.assert_same_acceleration(FLOATING)


if __name__ == "__main__":
    unittest.main()
