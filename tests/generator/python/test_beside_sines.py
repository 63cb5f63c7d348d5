"""The instructions beside a function's sines (passes/schedule.beside_sines): those that wait on no
joint sine or cosine, counted as the schedule line counts instructions. tools/trig_latency.py leaves
them out of the work that must follow joint_sincos."""

import unittest

from numeric_check import chain
from rbdcgen.frontend.scene import default_scene
from rbdcgen.graph import expr as ex
from rbdcgen.passes.schedule import beside_sines
from rbdcgen.passes.trace import trace_function


class Outputs:
    """What beside_sines reads of a traced function."""

    def __init__(self, exprs):
        self.exprs = exprs

    def output_exprs(self):
        return self.exprs


class SmallGraphs(unittest.TestCase):
    def test_only_what_waits_on_no_sine_counts(self):
        with ex.Graph():
            x, y, z, w = (ex.symbol("q", i) for i in range(4))
            # z·w and z + w wait on no sine; the product with sin x and the sum after it do
            self.assertEqual(beside_sines(Outputs([ex.sin(x) * y + z * w, z + w])), 2)
            self.assertEqual(beside_sines(Outputs([ex.cos(x) * (y + z)])), 1)
            self.assertEqual(beside_sines(Outputs([ex.sin(x), y])), 0)


class Chains(unittest.TestCase):
    def test_a_chains_mass_matrix_waits_on_its_sines_throughout(self):
        scene = default_scene()
        self.assertEqual(beside_sines(trace_function(chain(6), scene, "mass_matrix")), 0)
        # its inverse dynamics starts with the first joint's velocity terms, which turn with no angle
        inverse_dynamics = beside_sines(trace_function(chain(6), scene, "inverse_dynamics"))
        self.assertGreater(inverse_dynamics, 0)
        self.assertLess(inverse_dynamics, 40)


if __name__ == "__main__":
    unittest.main()
