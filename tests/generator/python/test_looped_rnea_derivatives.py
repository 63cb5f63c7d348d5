"""The looped RNEA derivatives (passes/looped_rnea_derivatives.py): the traced part writes each body's
transform (as the looped CRBA's) and gravity in the root's coordinates; the loop's flags follow the
function's inputs (a scene's zero inputs included); `auto` takes the loop where it costs less and,
past UNROLL_LIMIT ancestor steps, does not trace the unrolled recursion, for ∂τ and for ∂a (whose
looped solve then has the loop subtract ∂τ from its right-hand sides). The C++
loop is checked against the runtime by generator_verify_random_looped_rnea and its operation count by
product/test_operation_counts.py."""

import os
import unittest
from unittest import mock

from numeric_check import DATA, chain, evaluate, random_state

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph import expr as ex
from rbdcgen.passes import looped_rnea_derivatives as looped
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.passes.trace import trace_function
from rbdcgen.views.scalar import TracedModel

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
NAMES = ("inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives")


def scene(schedule, name="inverse_dynamics_derivatives", **keys):
    return scene_from_dict({"name": "x", "derivatives": [name], "schedule": schedule, **keys})


class LoopedRneaDerivatives(unittest.TestCase):
    def test_terms_are_the_transforms_and_gravity_in_root_coordinates(self):
        forced = scheduled_function(FLOATING, scene("looped_rnea"), "inverse_dynamics_derivatives")
        state = random_state(FLOATING, len(FLOATING.feet), 3)
        terms = evaluate(forced, state)
        transforms = evaluate(trace_function(FLOATING, scene("scalar"), "body_transforms"), state)["X"]
        self.assertEqual(terms["X"], transforms)
        with ex.Graph():
            gravity = ex.evaluate(TracedModel(FLOATING, scene("scalar")).gravity_in_base(), state)
        for got, expected in zip(terms["g"], gravity):
            self.assertAlmostEqual(got, expected, delta=1e-15)

    def test_flags_follow_the_inputs(self):
        flags = {}
        for name in NAMES:
            solve = scheduled_function(FLOATING, scene("looped_rnea", name), name).solve
            flags[name] = (solve.velocity, solve.acceleration, "nullptr}" not in solve.writer)
        self.assertEqual(flags, {"inverse_dynamics_derivatives": (True, True, True),
                                 "bias_derivatives": (True, False, True),
                                 "gravity_derivatives": (False, False, False)})
        at_rest = scheduled_function(FLOATING, scene("looped_rnea", zero_inputs=["v"]), "inverse_dynamics_derivatives")
        self.assertEqual((at_rest.solve.velocity, at_rest.solve.acceleration), (False, True))
        self.assertIn("nullptr, a, out", at_rest.solve.loops()[-1])

    def test_auto_keeps_the_small_recursion_unrolled_and_loops_a_long_chain(self):
        small = scheduled_function(FLOATING, scene("auto"), "inverse_dynamics_derivatives")
        self.assertTrue(small.schedule.startswith("scalar tree"), small.schedule)
        self.assertIn("looped RNEA derivatives", small.schedule)  # traced and counted, not taken
        links = 46
        self.assertGreater(looped.ancestor_steps(chain(links)), looped.UNROLL_LIMIT)
        large = scheduled_function(chain(links), scene("auto"), "inverse_dynamics_derivatives")
        self.assertTrue(large.schedule.startswith("looped RNEA derivatives"), large.schedule)
        self.assertIn("scalar tree not traced", large.schedule)
        # ∂a: every form that unrolls the CRBA or ∂τ left untraced; the looped solve's other loops remain
        # (on this fixed-base chain the low-rank product wins, its RNEA loop handing over its vectors)
        large = scheduled_function(chain(links), scene("auto", "forward_dynamics_derivatives"), "forward_dynamics_derivatives")
        self.assertTrue(large.schedule.startswith("low-rank product"), large.schedule)
        self.assertIn("looped CRBA", large.schedule)
        for form in ("scalar tree", "looped solve", "looped RNEA derivatives"):
            self.assertIn(form + " not traced", large.schedule)
        self.assertIsNotNone(large.solve.rnea)
        self.assertIsNone(large.solve.factor)  # M⁻¹ by the articulated-body recursion: no factor

    def test_the_loops_code_counts_against_the_front_end(self):
        """A 9-link chain's ∂a, as Panda's: the loop's own code (looped.CODE) with the traced part
        is past schedule.FRONT_END_LIMIT, so `auto` solves ∂τ traced instead; priced as if the loop
        took no code, it would take the loop (Panda: 1 300 → 1 040 ns, docs/performance.md, "A
        loop's code in the front end's budget")."""
        robot, name = chain(9), "forward_dynamics_derivatives"
        charged = scheduled_function(robot, scene("auto", name), name)
        self.assertTrue(charged.schedule.startswith("looped solve"), charged.schedule)
        with mock.patch.object(looped, "CODE", 0):
            free = scheduled_function(robot, scene("auto", name), name)
        self.assertTrue(free.schedule.startswith("looped RNEA derivatives"), free.schedule)

    def test_only_the_rnea_derivatives(self):
        """(A mimic-coupled robot's run on its tree: test_coupling.py, product/test_coupled_forms.py.)"""
        self.assertTrue(all(looped.has_looped_form(FLOATING, name) for name in NAMES))
        self.assertFalse(looped.has_looped_form(FLOATING, "forward_dynamics_derivatives"))


if __name__ == "__main__":
    unittest.main()
