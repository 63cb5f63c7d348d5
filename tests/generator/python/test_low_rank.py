"""∂q̈'s low-rank product (passes/looped_solve.py with low_rank, rbdc_gen::InverseTimesVectors): which
robots have it, and that `auto` takes it on a long fixed-base chain. The C++ product is checked against
the runtime by generator_verify_chain_low_rank and its operation count by
product/test_operation_counts.py."""

import os
import re
import unittest
from dataclasses import replace

from numeric_check import DATA, chain, geared

from rbdcgen.backend.emit import emit_body
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
        self.assertFalse(low_rank_applies(chain(20), scene(), NAME))  # M⁻¹'s rows do not pay: no M⁻¹
        self.assertFalse(low_rank_applies(geared(chain(60)), scene(), NAME))  # a rotor's terms
        self.assertFalse(low_rank_applies(FLOATING, scene(), NAME))  # a trunk and a branch

    def test_auto_takes_it_on_a_100_body_chain(self):
        fn = scheduled_function(chain(100), scene(), NAME)
        self.assertTrue(fn.schedule.startswith("low-rank product"), fn.schedule)
        self.assertIn("looped CRBA", fn.schedule)  # the form it beat, counted
        self.assertTrue(fn.solve.low_rank)
        self.assertEqual(fn.solve.solved_columns, 0)  # nothing solved: the feet's three columns are M⁻¹Jᵀ
        self.assertEqual(fn.solve.feet_columns, 3)

    def test_the_columns_it_does_not_read_are_neither_stored_nor_cleared(self):
        fn = scheduled_function(chain(32), scene("low_rank"), NAME)
        solve = fn.solve
        rhs = solve.terms[0].name
        self.assertEqual(len(solve.unread(rhs)), 32 * (solve.columns - solve.feet_columns))
        # the terms as the looped solve's helper emits them (backend/render.py)
        terms = replace(fn, outputs=solve.terms, solve=None, unread=((rhs, solve.unread(rhs)),))
        written = set()
        for line in emit_body(terms):
            written.update(int(k) for k in re.findall(r"\b%s\[(\d+)\]" % rhs, line))
            for start, end in re.findall(r"for \(int k = (\d+); k < (\d+); \+\+k\) %s\[k\]" % rhs, line):
                written.update(range(int(start), int(end)))
        self.assertTrue(written)
        self.assertFalse(written & set(solve.unread(rhs)))
        # without the unread entries, the same emitter clears them (what the 100-link chain paid for)
        cleared = set()
        for line in emit_body(replace(terms, unread=())):
            for start, end in re.findall(r"for \(int k = (\d+); k < (\d+); \+\+k\) %s\[k\]" % rhs, line):
                cleared.update(range(int(start), int(end)))
        self.assertTrue(cleared & set(solve.unread(rhs)))


if __name__ == "__main__":
    unittest.main()
