"""The feet's force-term derivatives as a loop (passes/looped_feet_forces.py): the traced axes and
moments rebuild ∂(Jᵀf)/∂q by the loop's rule (numpy here; the C++ loop against the runtime in
generator_verify_random_looped_rnea, its operation count in product/test_operation_counts.py);
`auto` keeps the unrolled term, measured faster, and a scene may force the loop; ∂q̈'s looped RNEA form
takes the loop (a coupled robot's does not: test_coupling.py); outputs with many zeros are cleared by
loops, each entry written once."""

import os
import re
import unittest
import unittest.mock
from collections import Counter

import numpy as np
from numeric_check import DATA, chain, evaluate, random_state

from rbdcgen.algorithms.forward_dynamics import dof_ancestors, dof_parents
from rbdcgen.backend import emit
from rbdcgen.backend.emit import ZERO_FILL_MIN, emit_body
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes import looped_feet_forces
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.passes.trace import trace_function

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
NAME = "feet_force_term_derivatives"


def scene(schedule, name=NAME):
    return scene_from_dict({"name": "x", "derivatives": [name], "schedule": schedule})


def rebuilt(robot, axes, moments, rows):
    """The loop's rule: (y, x) and (x, y) = ω_x · χ_y for x above y, (y, y) = ω_y · χ_y over `rows`,
    the trunk's (r, c) = ω_c · χ_r over its rotations."""
    w, chi = np.reshape(axes, (robot.nv, 3)), np.reshape(moments, (robot.nv, 3))
    out = np.zeros((robot.nv, robot.nv))
    for r in range(robot.root_dofs):
        for c in range(3):
            out[r, c] += w[c] @ chi[r]
    parents = dof_parents(robot)
    for y in rows:
        out[y, y] += w[y] @ chi[y]
        for x in dof_ancestors(parents, y):
            out[y, x] += w[x] @ chi[y]
            out[x, y] += w[x] @ chi[y]
    return out


class LoopedFeetForces(unittest.TestCase):
    def test_axes_and_moments_rebuild_the_unrolled_term(self):
        for robot in (FLOATING, chain(7)):
            looped = scheduled_function(robot, scene("looped_feet"), NAME)
            unrolled = trace_function(robot, scene("scalar"), NAME)
            for seed in range(3):
                state = random_state(robot, len(robot.feet), seed)
                terms = evaluate(looped, state)
                want = np.reshape(evaluate(unrolled, state)["dtau_e_dq"], (robot.nv, robot.nv), order="F")
                got = rebuilt(robot, terms["feet_axes"], terms["feet_moments"], looped.solve.rows)
                self.assertLess(np.max(np.abs(got - want)), 1e-12 * max(1.0, np.max(np.abs(want))))
                self.assertGreater(np.max(np.abs(want)), 1.0)  # a term to get wrong

    def test_auto_keeps_the_unrolled_term_which_runs_faster(self):
        # measured slower than the unrolled term on a 100-body chain too (looped_feet_forces.LOOP_WEIGHT)
        for robot in (FLOATING, chain(100)):
            fn = scheduled_function(robot, scene("auto"), NAME)
            self.assertTrue(fn.schedule.startswith("scalar tree"), fn.schedule)
            self.assertIn("looped feet force terms", fn.schedule)  # traced and counted, not taken
        self.assertIsNotNone(scheduled_function(chain(100), scene("looped_feet"), NAME).solve)

    def test_auto_loops_past_the_unrolled_terms_limit(self):
        """Past UNROLL_LIMIT pairs the unrolled term is not traced (its header's compile time)."""
        self.assertLess(looped_feet_forces.path_pairs(chain(100)), looped_feet_forces.UNROLL_LIMIT)
        self.assertGreater(looped_feet_forces.path_pairs(chain(130)), looped_feet_forces.UNROLL_LIMIT)
        fn = scheduled_function(chain(130), scene("auto"), NAME)
        self.assertTrue(fn.schedule.startswith("looped feet force terms"), fn.schedule)
        self.assertIn("scalar tree not traced (its entries: 8385 dof-ancestor pairs", fn.schedule)

    def test_the_looped_rnea_solve_takes_the_term_on_the_rnea_loop(self):
        fn = scheduled_function(FLOATING, scene("looped_rnea", "forward_dynamics_derivatives"),
                                "forward_dynamics_derivatives")
        self.assertTrue(fn.solve.rnea.feet)
        self.assertTrue(all(x.is_const(0.0) for x in fn.values["rhs"][:FLOATING.nv]))  # ∂q columns of row 0
        statements = fn.solve.loops()
        self.assertFalse(any(s.startswith("add_feet_force_term_derivatives") for s in statements))
        loop = next(i for i, s in enumerate(statements) if s.startswith("rnea_derivatives_loop"))
        solve = next(i for i, s in enumerate(statements) if s.startswith("ltdl_solve_columns"))
        self.assertLess(loop, solve)
        self.assertTrue(statements[loop].endswith(
            "out, FeetForceTerms<Scalar>{solve_feet_axes, solve_feet_moments});"), statements[loop])

    def test_many_zeros_are_cleared_by_loops_each_entry_once(self):
        fn = scheduled_function(chain(40), scene("looped_crba", "forward_dynamics_derivatives"),
                                "forward_dynamics_derivatives")
        values = fn.values["rhs"]
        self.assertGreaterEqual(sum(1 for x in values if x.is_const(0.0)), ZERO_FILL_MIN)
        written = Counter()  # rhs's entries by the statements that write them
        for statement in emit_body(fn):
            loop = re.fullmatch(r"for \(int k = (\d+); k < (\d+); \+\+k\) rhs\[k\] = Scalar\(0\);", statement)
            if loop:
                written.update(range(int(loop[1]), int(loop[2])))
            store = re.match(r"rhs\[(\d+)\] = ", statement)
            if store:
                written[int(store[1])] += 1
        self.assertEqual(set(written), set(range(len(values))))
        self.assertEqual(max(written.values()), 1)  # cleared whole first, the stored ones took 2
        with unittest.mock.patch.object(emit, "ZERO_RUNS_MAX", 0):  # too many runs: one loop
            self.assertEqual(emit_body(fn)[0], "for (int k = 0; k < %d; ++k) rhs[k] = Scalar(0);" % len(values))

if __name__ == "__main__":
    unittest.main()
