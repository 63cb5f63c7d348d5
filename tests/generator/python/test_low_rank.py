"""∂q̈'s low-rank product (passes/looped_solve.py with low_rank, rbdc_gen::InverseTimesVectors): which
robots have it, and that `auto` takes it on a long fixed-base chain. The C++ product is checked against
the runtime by generator_verify_chain_low_rank and its operation count by
product/test_operation_counts.py."""

import os
import unittest

from numeric_check import DATA, chain, geared

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes.looped_solve import low_rank_applies
from rbdcgen.passes.schedule import scheduled_function

NAME = "forward_dynamics_derivatives"
FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))


def scene(schedule="auto"):
    return scene_from_dict({"name": "x", "derivatives": [NAME], "schedule": schedule})


class LowRankProduct(unittest.TestCase):
    def test_a_long_fixed_base_chain_alone(self):
        self.assertTrue(low_rank_applies(chain(60), scene(), NAME))
        self.assertFalse(low_rank_applies(chain(60), scene(), "inverse_dynamics_derivatives"))
        self.assertFalse(low_rank_applies(chain(40), scene(), NAME))  # M⁻¹'s rows do not pay: no M⁻¹
        self.assertFalse(low_rank_applies(geared(chain(60)), scene(), NAME))  # a rotor's terms
        self.assertFalse(low_rank_applies(FLOATING, scene(), NAME))  # a trunk and a branch

    def test_auto_takes_it_on_a_100_body_chain(self):
        fn = scheduled_function(chain(100), scene(), NAME)
        self.assertTrue(fn.schedule.startswith("low-rank product"), fn.schedule)
        self.assertIn("looped CRBA", fn.schedule)  # the form it beat, counted
        self.assertTrue(fn.solve.low_rank)
        self.assertEqual(fn.solve.first_solved, 192)  # the feet's three columns from 200, in runs of 16


if __name__ == "__main__":
    unittest.main()
