"""∂a/∂τ as M⁻¹'s rows Zᵀ D⁻¹ Z (passes/looped_inverse.py): taken on a long chain, where it halves the
multiply-adds of Sᵀ's columns, and not on a short chain or a small tree; when taken, the looped
forward_dynamics_derivatives' right-hand sides leave Sᵀ out and its loops write da_dtau by
ltdl_inverse; when not, the banner gives both counts. Its operation count against the C++ loops:
product/test_operation_counts.py; its values against the runtime: generator_verify_chain_inverse
(tests/generator/CMakeLists.txt)."""

import os
import unittest

from numeric_check import DATA, chain

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.passes import differentiate, looped_solve
from rbdcgen.passes.looped_inverse import PAYS_BELOW, LoopedInverse, tau_by_inverse

FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
SCENE = scene_from_dict({"name": "x", "derivatives": ["forward_dynamics_derivatives"]})


class LoopedInverseTest(unittest.TestCase):
    def test_taken_on_a_long_chain_only(self):
        long = tau_by_inverse(chain(32), 3, differentiate.padded)
        self.assertEqual(long.first, 0)
        own, solve = long.comparison
        self.assertLessEqual(own, PAYS_BELOW * solve)
        self.assertIsNone(tau_by_inverse(chain(12), 3, differentiate.padded))
        self.assertIsNone(tau_by_inverse(FIXED, 3 * len(FIXED.feet), differentiate.padded))

    def test_rows_are_summed_in_tiles_along_paths(self):
        """rbdc_gen::path_size: up to four rows, each the parent of the one before; a branch ends a tile."""
        chain_tiles = list(LoopedInverse(parents=tuple(range(-1, 9)), first=0)._tiles(10))
        self.assertEqual(chain_tiles, [(9, 4), (5, 4), (1, 2)])
        branched = LoopedInverse(parents=(-1, 0, 1, 0, 3, 4), first=0)  # dofs 1-2 and 3-5 below dof 0
        self.assertEqual(list(branched._tiles(6)), [(5, 3), (2, 3)])
        self.assertEqual(list(branched._tiles(3)), [(2, 3)])

    def test_the_looped_form_solves_without_the_selection(self):
        robot = chain(32)
        function = looped_solve.looped_function(robot, SCENE, "forward_dynamics_derivatives")
        rhs = next(arg for arg in function.solve.terms if arg.name == "rhs")
        self.assertEqual(rhs.cols, differentiate.padded(2 * robot.nv + 3 * len(robot.feet)))
        self.assertNotIn("da_dtau", dict(function.solve.blocks))
        self.assertIn("ltdl_inverse<Scalar, 32, 0>(dof_tree, solve_L, solve_D_inv, da_dtau);", function.solve.loops())
        self.assertIn("ltdl_inverse", function.solve.emission("terms"))

    def test_the_banner_says_the_comparison_where_the_solve_is_kept(self):
        function = looped_solve.looped_function(chain(12), SCENE, "forward_dynamics_derivatives")
        self.assertIsNone(function.solve.taken_inverse)
        own, solve = function.solve.inverse.comparison
        self.assertGreater(own, PAYS_BELOW * solve)
        self.assertIn("∂a/∂τ solved with the rest (as M⁻¹'s rows Zᵀ D⁻¹ Z, %d multiply-adds" % own,
                      function.solve.emission("terms"))


if __name__ == "__main__":
    unittest.main()
