"""Limbs in SIMD lanes (rbdcgen/limbs.py, algorithms/lane_model.py, lane_functions.py): detection,
and every lane function equal to its scalar namesake on random states (expr.evaluate, lane by lane),
on the Mini Cheetah. The emitted C++ is checked against the runtime by `rbdc verify`."""

import unittest
from dataclasses import replace

import mini_cheetah
from numeric_check import evaluate, max_relative_error, random_state

from rbdcgen.flops import count_ops
from rbdcgen.lane_functions import SCALAR
from rbdcgen.limbs import LimbError, isomorphic_limbs
from rbdcgen.scene import default_scene
from rbdcgen.trace import trace_function


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class MiniCheetahLanes(unittest.TestCase):
    def test_limbs(self):
        robot = mini_cheetah.load()
        self.assertEqual(isomorphic_limbs(robot), ((1, 2, 3), (4, 5, 6), (7, 8, 9), (10, 11, 12)))

    def test_lane_functions_equal_scalar(self):
        robot = mini_cheetah.load()
        scene = default_scene()
        for name, scalar_name in SCALAR.items():
            lanes = trace_function(robot, scene, name)
            scalar = trace_function(robot, scene, scalar_name)
            for seed in (1, 2, 3):
                state = random_state(robot, len(robot.feet), seed)
                got = evaluate(lanes, lanes.lanes.with_lanes(state))
                want = evaluate(scalar, state)
                for output in want:
                    self.assertLess(max_relative_error(got[output], want[output]), 1e-13,
                                    (name, output, seed))
            # a lane operation counts once per lane: no fewer operations than the scalar code
            self.assertGreaterEqual(count_ops(lanes)["total"], count_ops(scalar)["total"] * 0.95)

    def test_limbs_must_match(self):
        robot = mini_cheetah.load()
        joints = list(robot.joints)
        joints[12] = replace(joints[12], type="prismatic")  # RH knee: no longer the same chain
        with self.assertRaises(LimbError):
            isomorphic_limbs(replace(robot, joints=tuple(joints)))


if __name__ == "__main__":
    unittest.main()
