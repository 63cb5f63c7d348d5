"""A robot with a singular M (docs/model.md, "Singular mass matrix"): the default scene leaves the
functions that need M⁻¹ out with a warning and keeps the rest; a scene that names one is refused
with the reason, naming the scene file and the joint."""
import tempfile
import unittest
from pathlib import Path

from rbdc_cli import ROOT, run_rbdc

LEAF = ROOT / "tests" / "data" / "massless_leaf.urdf"


class SingularMassTest(unittest.TestCase):
    def test_default_scene_leaves_the_inverse_functions_out(self):
        result = run_rbdc("flops", LEAF)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("left out: mass_matrix_factor, forward_dynamics, osc_open_chain, osc_closed_chain",
                      result.stderr)
        self.assertIn("inverse_dynamics", result.stdout)
        self.assertNotIn("forward_dynamics", result.stdout)

    def test_a_scene_that_names_forward_dynamics_is_refused(self):
        with tempfile.TemporaryDirectory() as directory:
            scene = Path(directory) / "fd_scene.yaml"
            scene.write_text("name: fd\nquantities: [inverse_dynamics, forward_dynamics]\n")
            result = run_rbdc("flops", LEAF, "--scene", scene)
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        for fragment in ("fd_scene.yaml", "'forward_dynamics' does not apply", "joint 'ja'",
                         "moving leaf with zero mass"):
            self.assertIn(fragment, result.stderr)


if __name__ == "__main__":
    unittest.main()
