"""The looped solve's blocks of columns on their own rows (passes/column_support.py): a limb's columns
sorted side by side, each block's rows closed under ancestors and holding its columns' rows, taken on
a branched tree and not on a chain; the RowSubset tables pair a row with its parent as the whole
tree's do; the looped forward_dynamics_derivatives then writes its columns where the order puts
them. Its values against the runtime: generator_verify_random_looped_rnea and _looped_crba
(random trees 0, 1 and 3 take it); its operation counts: product/test_operation_counts.py."""

import re
import unittest

import mini_cheetah
from numeric_check import chain

from rbdcgen.algorithms.forward_dynamics import dof_ancestors, dof_parents
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes import column_support, looped_solve
from rbdcgen.passes.column_support import ColumnSupport, planned, row_subset

# A trunk chain 0-2 with two legs of four dofs each (3-6 and 7-10) below dof 2.
LEGS = (-1, 0, 1, 2, 3, 4, 5, 2, 7, 8, 9)
SCENE = scene_from_dict({"name": "x", "derivatives": ["forward_dynamics_derivatives"], "schedule": "looped_rnea"})


def path_and_subtree(parents, j):
    """The rows ∂τ/∂q_j may be non-zero on: j, its descendants (the caller closes under ancestors)."""
    return [j] + [i for i in range(len(parents)) if j in dof_ancestors(parents, i)]


class ColumnSupportTest(unittest.TestCase):
    def legs_plan(self):
        n = len(LEGS)
        rows = [path_and_subtree(LEGS, j) for j in range(n)] * 2 + [[j] for j in range(n)] + [[6]] * 3 + [[10]] * 3
        return rows, planned(LEGS, rows, 48)

    def test_each_block_holds_its_columns_rows(self):
        rows, plan = self.legs_plan()
        self.assertIsNotNone(plan)
        self.assertEqual(sorted(plan.order), list(range(48)))
        for block in plan.blocks:
            self.assertEqual(block.first % column_support.RUN, 0)
            held = set(block.rows)
            self.assertEqual(list(block.rows), sorted(held, reverse=True))
            for j in held:
                self.assertTrue(set(dof_ancestors(LEGS, j)) <= held)  # closed under ancestors
            for c in plan.order[block.first:block.end]:
                self.assertTrue(c >= len(rows) or set(rows[c]) <= held)
        # a leg's own columns do not visit the other leg's rows
        leg = next(b for b in plan.blocks if 10 not in b.rows)
        self.assertTrue(set(leg.rows).isdisjoint(range(7, 11)))
        self.assertLess(plan.up_multiply_adds(), 48 * sum(len(dof_ancestors(LEGS, i)) for i in range(len(LEGS))))

    def test_not_taken_on_a_chain(self):
        parents = tuple(range(-1, 11))
        rows = [list(range(12))] * 24
        self.assertIsNone(planned(parents, rows, 24))

    def test_a_subset_pairs_rows_as_the_whole_tree_does(self):
        declaration = row_subset(LEGS, (6, 5, 4, 3, 2, 1, 0), "rows")
        tables = re.findall(r"\{([^{}]*)\}", declaration)
        self.assertEqual(tables[0], "6, 5, 4, 3, 2, 1, 0")
        self.assertEqual(tables[1], "0, 0, 1, 3, 6, 10, 15, 21")  # descendants among the rows, per row
        self.assertEqual(tables[2].split(", ")[:3], ["6", "6", "5"])  # deepest first
        self.assertEqual(tables[4], "1, 0, 1, 0, 1, 0, 0")  # rows 6-5, 4-3, 2-1 in pairs

    def test_a_chain_keeps_its_columns_in_order(self):
        function = looped_solve.looped_function(chain(6), SCENE, "forward_dynamics_derivatives", rnea=True)
        self.assertIsNone(function.solve.support)
        self.assertIn("ltdl_solve_columns<", "\n".join(function.solve.loops()))

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_the_looped_form_sorts_its_columns(self):
        robot = mini_cheetah.load()
        function = looped_solve.looped_function(robot, SCENE, "forward_dynamics_derivatives", rnea=True)
        support = function.solve.support
        self.assertIsInstance(support, ColumnSupport)
        loops = "\n".join(function.solve.loops())
        self.assertIn("SubtractedFromColumns<Scalar, %d, %d, true> out{solve_rhs, solve_rhs_place}"
                      % (robot.nv, function.solve.columns), loops)
        self.assertIn("out, FeetForceTerms<Scalar>{solve_feet_axes, solve_feet_moments});", loops)
        self.assertEqual(loops.count("ltdl_solve_column_range"), len(support.blocks))
        self.assertEqual(function.solve.column_order, support.order)
        self.assertIn("blocks, ltdl_solve_column_range solves each, its L⁻ᵀ over its columns' non-zero rows only",
                      function.solve.emission("terms"))
        self.assertEqual(list(support.parents), dof_parents(robot))
        # the traced right-hand sides are where the order puts them: Sᵀ's 1 of dof 6 at its place
        rhs = function.values["rhs"]
        columns = function.solve.columns
        tau_of_dof_6 = 2 * robot.nv + 0  # the first of Sᵀ's columns (floating base: dofs 6 …)
        self.assertTrue(rhs[6 * columns + support.place()[tau_of_dof_6]].is_const(1.0))


if __name__ == "__main__":
    unittest.main()
