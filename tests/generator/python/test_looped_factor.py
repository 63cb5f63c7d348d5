"""mass_matrix_factor's looped form (passes/looped_factor.py): its traced part writes exactly M's
entries at each dof's ancestors (packed, nearest first) and M's diagonal; the loop's operation count
is the factorisation's trip count (closed form on a chain); `auto` keeps the unrolled factor for a
small tree and, past UNROLL_LIMIT, does not trace it and takes the loop, for mass_matrix_factor and
for forward dynamics' factor form alike. The C++ loop itself is checked against the runtime's factor
by generator_verify_random_looped_factor (tests/generator/CMakeLists.txt)."""

import os
import unittest

from numeric_check import DATA, chain, evaluate, random_state

from rbdcgen.algorithms.forward_dynamics import dof_ancestors, dof_parents
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph.flops import count_ops
from rbdcgen.passes import looped_factor
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.passes.trace import trace_function

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))


def scene(schedule, quantities=("mass_matrix_factor",)):
    return scene_from_dict({"name": "x", "quantities": list(quantities), "schedule": schedule})


class LoopedFactor(unittest.TestCase):
    def test_terms_are_the_mass_matrix_entries_the_factorisation_reads(self):
        for robot in (FLOATING, chain(7)):
            looped = scheduled_function(robot, scene("looped_factor"), "mass_matrix_factor")
            self.assertIn("looped factor", looped.schedule)
            mass = trace_function(robot, scene("scalar", ("mass_matrix",)), "mass_matrix")
            parents, n = dof_parents(robot), robot.nv
            for seed in range(3):
                state = random_state(robot, len(robot.feet), seed)
                M = evaluate(mass, state)["M"]          # column-major
                terms = evaluate(looped, state)
                packed = [M[j * n + i] for i in range(n) for j in dof_ancestors(parents, i)]
                self.assertEqual(len(terms["L"]), len(packed))
                for got, want in zip(terms["L"], packed):
                    self.assertAlmostEqual(got, want, delta=1e-14 * max(1.0, abs(want)))
                for k in range(n):
                    self.assertAlmostEqual(terms["D"][k], M[k * n + k], delta=1e-14 * abs(M[k * n + k]))

    def test_operations_count_the_loop_by_trip_count(self):
        n = 9  # a chain: dof k has ancestors 0 … k−1 and ancestor i a row of i entries, so n(n−1)/2
        # pairs and Σ_k k(k−1)/2 = n(n−1)(n−2)/6 row entries
        fn = scheduled_function(chain(n), scene("looped_factor"), "mass_matrix_factor")
        pairs, rows = n * (n - 1) // 2, n * (n - 1) * (n - 2) // 6
        self.assertEqual(fn.solve.operations(), {"div": n, "mul": 2 * pairs + rows, "add": pairs + rows})
        terms = trace_function(chain(n), scene("scalar"), looped_factor.TERMS)
        total = count_ops(terms)["total"] + n + 3 * pairs + 2 * rows
        self.assertEqual(count_ops(fn)["total"], total)

    def test_auto_unrolls_a_small_factor_and_loops_a_large_one(self):
        small = scheduled_function(FLOATING, scene("auto"), "mass_matrix_factor")
        self.assertTrue(small.schedule.startswith("scalar tree"), small.schedule)
        self.assertIsNone(small.solve)
        links = 55
        self.assertGreater(looped_factor.factor_multiply_adds(dof_parents(chain(links))), looped_factor.UNROLL_LIMIT)
        large = scheduled_function(chain(links), scene("auto"), "mass_matrix_factor")
        self.assertIsInstance(large.solve, looped_factor.LoopedFactor)  # its entries by the looped CRBA
        self.assertIn("scalar tree not traced", large.schedule)
        dynamics = scheduled_function(chain(links), scene("auto", ("forward_dynamics",)), "forward_dynamics")
        self.assertIn("scalar tree not traced", dynamics.schedule)


if __name__ == "__main__":
    unittest.main()
