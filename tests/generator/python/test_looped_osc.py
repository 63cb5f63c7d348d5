"""The looped operational-space columns (passes/looped_osc.py): the traced part's Λ, b, per-body
S_i, w_i and the trunk's frame, carried as osc_columns_loop does (rbdc_gen/osc.hpp, here in Python), give the unrolled
recursion's J̄ᵀ; `auto` keeps the unrolled columns on a small tree and, past UNROLL_LIMIT, takes the
loop without tracing them. The C++ loop is checked against the runtime by
generator_verify_random_looped_osc and its operation count by product/test_operation_counts.py."""

import os
import unittest
import unittest.mock

from numeric_check import DATA, evaluate, geared, max_relative_error, random_state

from rbdcgen.algorithms.crba import depth_first_order
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes import looped_osc
from rbdcgen.passes.schedule import scheduled_function

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
NAMES = ("osc_open_chain", "osc_closed_chain")


def scene(schedule, name):
    return scene_from_dict({"name": "x", "quantities": [name], "schedule": schedule})


def carried_columns(robot, columns):
    """osc_columns_loop in Python: column k (bodies in depth-first order) starts as −w_k, then each
    ancestor i, nearest first, subtracts (S_i · c) w_i; then (n, f) in world coordinates go to the
    trunk's, (R_0ᵀ (n − p_0 × f), R_0ᵀ f). Returns J̄ᵀ column-major by joint."""
    terms = {body: columns[12 * (p - 1):12 * p] for p, body in enumerate(depth_first_order(robot)) if p}
    R0, p0 = columns[-12:-3], columns[-3:]

    def trunk(v):  # R_0ᵀ v
        return [sum(R0[3 * a + b] * v[a] for a in range(3)) for b in range(3)]
    JbarT = []
    for k in range(1, robot.nb):
        c = [-x for x in terms[k][6:]]
        i = robot.parent[k]
        while i != 0:
            S, w = terms[i][:6], terms[i][6:]
            s = sum(a * b for a, b in zip(S, c))
            c = [x - s * y for x, y in zip(c, w)]
            i = robot.parent[i]
        n, f = c[:3], c[3:]
        p_x_f = [p0[1] * f[2] - p0[2] * f[1], p0[2] * f[0] - p0[0] * f[2], p0[0] * f[1] - p0[1] * f[0]]
        JbarT += trunk([x - y for x, y in zip(n, p_x_f)]) + trunk(f)
    return JbarT


class LoopedOsc(unittest.TestCase):
    def test_loop_of_the_terms_is_the_unrolled_recursion(self):
        self.assertGreater(looped_osc.ancestor_steps(FLOATING), 0)
        for name in NAMES:
            looped = scheduled_function(FLOATING, scene("looped_osc", name), name)
            self.assertIn("looped operational-space columns", looped.schedule)
            unrolled = scheduled_function(FLOATING, scene("scalar", name), name)
            for seed in range(3):
                state = random_state(FLOATING, len(FLOATING.feet), seed)
                got, want = evaluate(looped, state), evaluate(unrolled, state)
                for output in ("Lambda", "b"):
                    self.assertLess(max_relative_error(got[output], want[output]), 1e-13, (name, output))
                self.assertLess(max_relative_error(carried_columns(FLOATING, got["columns"]), want["JbarT"]),
                                1e-13, name)

    def test_auto_unrolls_a_small_tree_and_loops_past_the_limit(self):
        small = scheduled_function(FLOATING, scene("auto", "osc_open_chain"), "osc_open_chain")
        self.assertTrue(small.schedule.startswith("scalar tree"), small.schedule)
        self.assertIn("looped operational-space columns", small.schedule)  # traced and counted, not taken
        with unittest.mock.patch.object(looped_osc, "UNROLL_LIMIT", 0):
            large = scheduled_function(FLOATING, scene("auto", "osc_open_chain"), "osc_open_chain")
        self.assertTrue(large.schedule.startswith("looped operational-space columns"), large.schedule)
        self.assertIn("scalar tree not traced (its columns", large.schedule)

    def test_rotors_have_no_looped_columns(self):
        self.assertTrue(looped_osc.has_looped_form(FLOATING, "osc_closed_chain"))
        self.assertFalse(looped_osc.has_looped_form(FLOATING, "mass_matrix"))
        self.assertFalse(looped_osc.has_looped_form(geared(FLOATING), "osc_open_chain"))
        self.assertIsNone(scheduled_function(geared(FLOATING), scene("looped_osc", "osc_open_chain"),
                                             "osc_open_chain").solve)


if __name__ == "__main__":
    unittest.main()
