"""Golden test: the generated code of a small robot (tests/generator/golden/two_link.urdf, fixed
base, default scene) equals the committed files in golden/expected/ byte for byte. After an intended
change of the output, review the diff and refresh with RBDC_UPDATE_GOLDEN=1."""
import filecmp
import os
import shutil
import tempfile
import unittest
from pathlib import Path

from rbdc_cli import run_rbdc

GOLDEN = Path(__file__).resolve().parents[1] / "golden"


class GoldenTest(unittest.TestCase):
    def test_two_link_output_matches_expected(self):
        with tempfile.TemporaryDirectory() as out:
            result = run_rbdc("generate", GOLDEN / "two_link.urdf", "--fixed-base", "-o", out)
            self.assertEqual(result.returncode, 0, result.stderr)
            if os.environ.get("RBDC_UPDATE_GOLDEN") == "1":
                shutil.rmtree(GOLDEN / "expected", ignore_errors=True)
                shutil.copytree(out, GOLDEN / "expected")
            expected = sorted(p.relative_to(GOLDEN / "expected").as_posix()
                              for p in (GOLDEN / "expected").rglob("*") if p.is_file())
            produced = sorted(p.relative_to(out).as_posix() for p in Path(out).rglob("*") if p.is_file())
            self.assertEqual(produced, expected)
            _, mismatch, errors = filecmp.cmpfiles(GOLDEN / "expected", out, expected, shallow=False)
            self.assertEqual(mismatch + errors, [], "generated code differs from golden/expected")
            self.assertIn("two_link/full/mass_matrix.hpp", expected)


if __name__ == "__main__":
    unittest.main()
