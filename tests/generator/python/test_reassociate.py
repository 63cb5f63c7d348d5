"""Sums added in their terms' order of arrival (rbdcgen.graph.reassociate): the critical path
shortens, the operation count and the signs stay, a sum used twice is left whole, and a traced robot
function keeps its values and its counts with a path no longer than the formula's order gives."""

import os
import unittest
from unittest import mock

from numeric_check import DATA, evaluate, max_relative_error, random_state
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene
from rbdcgen.graph import expr as ex
from rbdcgen.graph.flops import count_ops
from rbdcgen.graph.latency import critical_path, critical_path_of
from rbdcgen.graph.reassociate import reassociate
from rbdcgen.passes import trace

ROBOT = load_ir(os.path.join(DATA, "tiny_fixed.json"))


def operations(outputs):
    """The operations reaching `outputs`, additions and subtractions alike (a term's sign picks one)."""
    return sorted("add" if node.op == "sub" else node.op
                  for node in ex.reachable(outputs) if node.op not in ("const", "sym"))


class Sums(unittest.TestCase):
    def setUp(self):
        self.graph = ex.Graph().__enter__()
        self.q = [ex.symbol("q", k) for k in range(6)]

    def tearDown(self):
        self.graph.__exit__(None, None, None)

    def late(self, steps):
        """A term ready only after `steps` dependent multiplications."""
        x = self.q[5]
        for _ in range(steps):
            x = x * self.q[5]
        return x

    def test_the_late_term_is_added_last(self):
        a, b, c, d = self.q[:4]
        late = self.late(6)
        formula = (((late + a) - b) + c * d) - a * b  # the late term first, as a formula may read
        [rebuilt] = reassociate([formula])
        self.assertLess(critical_path_of([rebuilt]), critical_path_of([formula]))
        self.assertEqual(operations([rebuilt]), operations([formula]))
        inputs = {"q": [0.3, -1.7, 2.9, 0.45, -3.1, 1.05]}
        [want], [got] = ex.evaluate([formula], inputs), ex.evaluate([rebuilt], inputs)
        self.assertAlmostEqual(got, want, places=13)
        self.assertTrue(late in rebuilt.args, "the late term joins in the last addition")

    def test_signs_survive_every_order(self):
        a, b, c, d, e = self.q[:5]
        formula = ((a - (b + c)) - (d - e)) + self.late(3)
        [rebuilt] = reassociate([formula])
        inputs = {"q": [1.25, 0.5, -2.0, 4.0, 0.125, 0.75]}
        self.assertAlmostEqual(ex.evaluate([rebuilt], inputs)[0], ex.evaluate([formula], inputs)[0], places=13)
        self.assertEqual(operations([rebuilt]), operations([formula]))

    def test_a_sum_used_twice_stays_whole(self):
        a, b, c = self.q[:3]
        shared = a + b
        formula = (shared + self.late(4)) + c
        other = shared * c
        rebuilt = reassociate([formula, other])
        self.assertIn(shared, ex.reachable(rebuilt))
        self.assertIs(rebuilt[1], other)
        self.assertEqual(operations(rebuilt), operations([formula, other]))


class TracedFunctions(unittest.TestCase):
    def test_counts_and_values_kept_and_paths_not_longer(self):
        scene = default_scene()
        for name in ("inverse_dynamics", "mass_matrix", "forward_dynamics"):
            arrived = trace.trace_function(ROBOT, scene, name)
            with mock.patch.object(trace, "reassociate", list):
                formula = trace.trace_function(ROBOT, scene, name)
            self.assertEqual(count_ops(arrived), count_ops(formula), name)
            self.assertLessEqual(critical_path(arrived), critical_path(formula), name)
            state = random_state(ROBOT, len(ROBOT.feet), 3)
            got, want = evaluate(arrived, state), evaluate(formula, state)
            for output in want:
                self.assertLess(max_relative_error(got[output], want[output]), 1e-13, (name, output))


if __name__ == "__main__":
    unittest.main()
