"""Folding rules, hash-consing (CSE), reachability (DCE) and the DAG evaluator of rbdcgen.graph.expr."""

import math
import unittest

import numeric_check  # noqa: F401  (puts the generator on sys.path)
from rbdcgen.graph import expr as ex


class Folding(unittest.TestCase):
    def setUp(self):
        self.graph = ex.Graph().__enter__()
        self.x = ex.symbol("q", 0)
        self.y = ex.symbol("q", 1)

    def tearDown(self):
        self.graph.__exit__(None, None, None)

    def test_identities_fold_away(self):
        x = self.x
        self.assertIs(x * 1, x)
        self.assertIs(1 * x, x)
        self.assertIs(x + 0, x)
        self.assertIs(0 + x, x)
        self.assertIs(x - 0, x)
        self.assertIs(x / 1, x)
        self.assertTrue((x * 0).is_const(0.0))
        self.assertTrue((0 / x).is_const(0.0))
        self.assertTrue((x - x).is_const(0.0))
        self.assertIs(-(-x), x)

    def test_constants_fold(self):
        self.assertEqual((ex.const(2.0) * 3.5).value, 7.0)
        self.assertEqual((ex.const(2.0) - 3.5).value, -1.5)
        self.assertEqual(ex.sin(ex.const(0.5)).value, math.sin(0.5))
        self.assertEqual(ex.sqrt(ex.const(4.0)).value, 2.0)
        self.assertIs(ex.const(-0.0), ex.const(0.0))

    def test_signs_are_absorbed(self):
        x, y = self.x, self.y
        self.assertIs(-1 * x, -x)
        self.assertEqual((x + (-y)).op, "sub")
        self.assertEqual(((-x) + y).op, "sub")
        self.assertIs(x - (-y), x + y)
        self.assertIs((-x) * (-y), x * y)
        self.assertIs(-(x - y), y - x)
        self.assertIs((-2.0) * x, -(2.0 * x))

    def test_a_rotated_negation_stays_a_subtraction(self):
        """lane_rotate takes a negation outside, so that the sum it joins folds it in."""
        x, y = ex.symbol("lane_v", 0), ex.symbol("lane_v", 1)
        rotated = ex.lane_rotate(-y, 2)
        self.assertEqual(rotated.op, "neg")
        self.assertEqual((x + rotated).op, "sub")
        self.assertIs(ex.lane_rotate(ex.lane_const([1.0, 2.0, 3.0, 4.0]), 2), ex.lane_const([3.0, 4.0, 1.0, 2.0]))

    def test_a_lane_of_a_rotated_value_is_read_where_it_came_from(self):
        x = ex.symbol("lane_v", 0) * ex.symbol("lane_v", 1)
        self.assertIs(ex.lane_get(ex.lane_rotate(x, 2), 1), ex.lane_get(x, 3))
        self.assertIs(ex.lane_get(ex.lane_rotate(-x, 2), 0), -ex.lane_get(x, 2))

    def test_constant_factors_combine(self):
        x = self.x
        node = 3.0 * (2.0 * x)
        self.assertEqual(node.op, "mul")
        self.assertEqual(node.args[0].value, 6.0)
        self.assertIs(node.args[1], x)

    def test_no_reassociation_of_variables(self):
        x, y, z = self.x, self.y, ex.symbol("q", 2)
        self.assertIsNot((x + y) + z, x + (y + z))

    def test_division_by_constant_zero_is_refused(self):
        with self.assertRaises(ZeroDivisionError):
            self.x / 0.0


class SharingAndReachability(unittest.TestCase):
    def test_structurally_equal_subtrees_are_one_node(self):
        with ex.Graph() as graph:
            x, y = ex.symbol("q", 0), ex.symbol("v", 0)
            first = ex.sin(x) * y + ex.cos(x)
            second = ex.cos(x) + y * ex.sin(x)       # commuted operands
            self.assertIs(first, second)
            count = len(graph.nodes)
            ex.sin(x) * y + ex.cos(x)
            self.assertEqual(len(graph.nodes), count)

    def test_dead_nodes_are_not_reachable(self):
        with ex.Graph():
            x, y = ex.symbol("q", 0), ex.symbol("q", 1)
            live = x * y
            dead = ex.sqrt(x) + y
            order = ex.reachable([live])
            self.assertIn(live, order)
            self.assertNotIn(dead, order)
            self.assertLess(order.index(x), order.index(live))

    def test_evaluator(self):
        with ex.Graph():
            x, y = ex.symbol("q", 0), ex.symbol("q", 1)
            out = [ex.sin(x) * y - x / y, ex.sqrt(y)]
            got = ex.evaluate(out, {"q": [0.3, 4.0]})
        self.assertEqual(got, [math.sin(0.3) * 4.0 - 0.3 / 4.0, 2.0])

    def test_final_negations_are_absorbed_where_free(self):
        with ex.Graph():
            x, y, z = ex.symbol("q", 0), ex.symbol("q", 1), ex.symbol("q", 2)
            (product,) = ex.absorb_negations([-(2.0 * x)])
            self.assertEqual((product.op, product.args[0].value), ("mul", -2.0))
            outputs = [-(x * y + 3.0 * z)]
            (rewritten,) = ex.absorb_negations(outputs)
            self.assertEqual(rewritten.op, "sub")
            self.assertFalse(any(n.op == "neg" for n in ex.reachable([rewritten])))
            state = {"q": [0.3, -1.2, 2.5]}
            self.assertEqual(ex.evaluate([rewritten], state), ex.evaluate(outputs, state))
            shared = 2.0 * x
            kept = ex.absorb_negations([-shared, shared * y])
            self.assertEqual(kept[0].op, "neg")  # the product has another user: keep one multiply

    def test_nodes_need_a_graph(self):
        with self.assertRaises(RuntimeError):
            ex.symbol("q", 0)


if __name__ == "__main__":
    unittest.main()
