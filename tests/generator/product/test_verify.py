"""`rbdc verify` fails when generated code and runtime disagree: code generated for the golden robot
is checked against the runtime loading the same robot with one mass changed."""
import argparse
import io
import sys
import tempfile
import unittest
from contextlib import redirect_stdout
from pathlib import Path

from rbdc_cli import ROOT

sys.path.insert(0, str(ROOT / "generator"))
from rbdcgen.commands import verify  # noqa: E402
from rbdcgen.frontend.layout import find_layout  # noqa: E402
from rbdcgen.commands.pipeline import compile_robot  # noqa: E402

GOLDEN_ROBOT = Path(__file__).resolve().parents[1] / "golden" / "two_link.urdf"


class VerifyDetectsMismatchTest(unittest.TestCase):
    def test_changed_mass_fails_verification(self):
        layout = find_layout()
        with tempfile.TemporaryDirectory() as directory:
            heavier = Path(directory) / "two_link.urdf"
            heavier.write_text(GOLDEN_ROBOT.read_text().replace('<mass value="0.5"/>', '<mass value="0.6"/>'))
            compilation = compile_robot(GOLDEN_ROBOT, base="fixed", layout=layout)
            args = argparse.Namespace(states=5, seed=1, tolerance=1e-10, mimic="couple", topology=None)
            report = io.StringIO()
            with redirect_stdout(report):
                status = verify.build_and_run([heavier], [compilation], Path(directory) / "work", args, layout)
        self.assertEqual(status, 1, report.getvalue())
        self.assertIn("mass_matrix.M", report.getvalue())
        self.assertIn("FAIL", report.getvalue())
        # Kinematics does not see the mass, so it still passes.
        self.assertRegex(report.getvalue(), r"feet_positions\.p +\S+ +\S+ +\d+\n")


if __name__ == "__main__":
    unittest.main()
