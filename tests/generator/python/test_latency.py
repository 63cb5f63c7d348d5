"""The critical path of a traced function (rbdcgen.graph.latency): exact on small graphs, a sum of a
product an FMA where that is sooner, and on a serial chain it grows by the same cycles per link."""

import unittest

from numeric_check import chain
from rbdcgen.frontend.scene import default_scene
from rbdcgen.graph import expr as ex
from rbdcgen.graph.latency import FMA, JOINT_SINCOS, LATENCY, critical_path, critical_path_of
from rbdcgen.passes.trace import trace_function


class SmallGraphs(unittest.TestCase):
    def setUp(self):
        self.graph = ex.Graph().__enter__()
        self.x, self.y, self.z, self.w = (ex.symbol("q", i) for i in range(4))

    def tearDown(self):
        self.graph.__exit__(None, None, None)

    def test_a_product_added_is_one_fma(self):
        x, y, z, w = self.x, self.y, self.z, self.w
        self.assertEqual(critical_path_of([x * y + z]), FMA)
        self.assertEqual(critical_path_of([z - x * y]), FMA)
        # two products side by side, then their sum: sooner than either product fused after the other
        self.assertEqual(critical_path_of([x * y + z * w]), LATENCY["mul"] + LATENCY["add"])
        # a product whose other operand comes late: the plain sum after that operand beats the FMA
        late = ((z + w) + w) + w
        self.assertEqual(critical_path_of([x * y + late]), 3 * LATENCY["add"] + LATENCY["add"])

    def test_a_product_used_twice_fuses_into_each_addition(self):
        x, y, z, w = self.x, self.y, self.z, self.w
        p = x * y  # g++ contracts across statements: each sum may repeat the product in its FMA
        self.assertEqual(critical_path_of([p + z, p - w]), FMA)
        self.assertEqual(critical_path_of([p * z]), 2 * LATENCY["mul"])  # a product of it is not an FMA

    def test_dependent_chains_add_up_and_the_longest_output_counts(self):
        x, y, z, w = self.x, self.y, self.z, self.w
        self.assertEqual(critical_path_of([((x + y) + z) + w]), 3 * LATENCY["add"])
        self.assertEqual(critical_path_of([x + y, (x + y) / z]), LATENCY["add"] + LATENCY["div"])
        self.assertEqual(critical_path_of([ex.sin(x) * y]), JOINT_SINCOS + LATENCY["mul"])
        self.assertEqual(critical_path_of([x, ex.const(2.0)]), 0)


class Chains(unittest.TestCase):
    def path(self, links, name="inverse_dynamics"):
        return critical_path(trace_function(chain(links), default_scene(), name))

    def test_each_link_adds_the_same_cycles(self):
        # the chain's axes repeat every 3 links (x, y, z); past its first links nothing folds away
        p9, p15, p21 = self.path(9), self.path(15), self.path(21)
        self.assertEqual(p21 - p15, p15 - p9)
        self.assertGreater((p15 - p9) / 6, 2 * FMA)  # the outward and inward passes, each a few steps deep

    def test_mass_matrix_path_is_shorter_than_forward_dynamics(self):
        # forward dynamics needs M (then its factor and solve): its path contains one through M
        self.assertLess(self.path(8, "mass_matrix"), self.path(8, "forward_dynamics"))


if __name__ == "__main__":
    unittest.main()
