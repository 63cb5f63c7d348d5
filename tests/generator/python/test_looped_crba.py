"""The looped CRBA (passes/looped_crba.py): its traced part writes each body's X_λ(i)^i = X_J X_T as
(E, r), the transform the unrolled CRBA applies; `auto` keeps the unrolled CRBA on a small tree and,
past UNROLL_LIMIT ancestor steps, does not trace it and takes the loop, for mass_matrix and for the
looped factor's entries. The C++ loop is checked against the runtime by
generator_verify_random_looped_crba and its operation count by product/test_operation_counts.py."""

import os
import unittest

from numeric_check import DATA, chain, evaluate, geared, random_state

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph import expr as ex
from rbdcgen.graph import spatial as sp
from rbdcgen.passes import looped_crba
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.views.scalar import TracedModel

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))


def scene(schedule, quantities=("mass_matrix",)):
    return scene_from_dict({"name": "x", "quantities": list(quantities), "schedule": schedule})


class LoopedCrba(unittest.TestCase):
    def test_terms_are_the_transforms_the_crba_applies(self):
        for robot in (FLOATING, chain(5)):
            looped = scheduled_function(robot, scene("looped_crba"), "mass_matrix")
            self.assertIn("looped CRBA", looped.schedule)
            state = random_state(robot, len(robot.feet), 0)
            X = evaluate(looped, state)["X"]
            with ex.Graph():
                m = TracedModel(robot, scene("scalar"))
                force = sp.vec([0.3, -1.2, 0.7, 2.0, 0.1, -0.4])
                for i in range(1, robot.nb):  # the unrolled CRBA's Xᵀ F, against (E, r) applied
                    want = ex.evaluate(m.X_up(i).force_T(force), state)
                    E = [X[12 * (i - 1) + k] for k in range(9)]
                    r = X[12 * (i - 1) + 9:12 * i]
                    u = [sum(E[3 * k + j] * force[3 + k].value for k in range(3)) for j in range(3)]
                    n = [sum(E[3 * k + j] * force[k].value for k in range(3)) for j in range(3)]
                    n = [n[0] + r[1] * u[2] - r[2] * u[1], n[1] + r[2] * u[0] - r[0] * u[2],
                         n[2] + r[0] * u[1] - r[1] * u[0]]
                    for got, expected in zip(n + u, want):
                        self.assertAlmostEqual(got, expected, delta=1e-13)

    def test_auto_unrolls_a_small_crba_and_loops_a_large_one(self):
        small = scheduled_function(FLOATING, scene("auto"), "mass_matrix")
        self.assertTrue(small.schedule.startswith("scalar tree"), small.schedule)
        self.assertIn("looped CRBA", small.schedule)  # traced and counted, not taken
        links = 46
        self.assertGreater(looped_crba.ancestor_steps(chain(links)), looped_crba.UNROLL_LIMIT)
        for name in ("mass_matrix", "mass_matrix_factor"):
            large = scheduled_function(chain(links), scene("auto", (name,)), name)
            self.assertIn("looped CRBA", large.schedule if name == "mass_matrix" else large.solve.emission("t"))
            self.assertEqual(large.solve.crba.packed if name == "mass_matrix_factor" else large.solve.packed,
                             name == "mass_matrix_factor")

    def test_rotors_and_other_functions_have_no_looped_crba(self):
        self.assertTrue(looped_crba.has_looped_form(FLOATING, "mass_matrix"))
        self.assertFalse(looped_crba.has_looped_form(FLOATING, "bias"))
        self.assertFalse(looped_crba.has_looped_form(geared(FLOATING), "mass_matrix"))
        forced = scheduled_function(geared(FLOATING), scene("looped_crba"), "mass_matrix")
        self.assertIsNone(forced.solve)  # the scalar tree, which carries the rotor


if __name__ == "__main__":
    unittest.main()
