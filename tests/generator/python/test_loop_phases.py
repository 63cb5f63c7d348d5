"""tools/loop_phases.py finds every phase of rnea_derivatives_loop in the generated header it
instruments, and its instrumented header and driver compile against a bundled robot whose
inverse_dynamics_derivatives is looped (humanoid32). The timing itself is a measurement
(docs/performance.md, "The ∂τ loop phase by phase"), not a test."""

import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

import mini_cheetah
import tools_module

TOOL = tools_module.load("loop_phases")
GENERATED = Path(mini_cheetah.ROOT) / "generated"


class LoopPhasesTest(unittest.TestCase):
    def test_a_marker_before_every_phase_and_after_the_last(self):
        text = TOOL.instrumented((GENERATED / "rbdc_gen" / "rnea_derivatives.hpp").read_text())
        for k in range(len(TOOL.PHASES) + 1):
            self.assertEqual(text.count(f"RBDC_PHASE({k});"), 1, k)
        self.assertLess(text.index("RBDC_PHASE(0);"), text.index("root_frames(tree, X"))
        self.assertGreater(text.index(f"RBDC_PHASE({len(TOOL.PHASES)});"), text.index("// the trunk's block"))

    def test_a_phase_that_moved_is_an_error(self):
        with self.assertRaises(SystemExit):
            TOOL.instrumented("#pragma once\n// rnea_derivatives_loop as it no longer reads\n")

    def test_the_instrumented_loop_compiles_for_humanoid32(self):
        self.assertIn("looped RNEA derivatives",
                      (GENERATED / "humanoid32" / "derivatives" / "inverse_dynamics_derivatives.hpp").read_text())
        with tempfile.TemporaryDirectory() as scratch:
            tree = Path(scratch) / "gen"
            shutil.copytree(GENERATED / "rbdc_gen", tree / "rbdc_gen")
            header = tree / "rbdc_gen" / "rnea_derivatives.hpp"
            header.write_text(TOOL.instrumented(header.read_text()))
            source = Path(scratch) / "driver.cpp"
            source.write_text(TOOL.driver("humanoid32", floating=True))
            subprocess.run(["c++", "-std=c++17", "-fsyntax-only", "-march=x86-64-v2", f"-I{tree}", f"-I{GENERATED}",
                            "-I/usr/include/eigen3", str(source)], check=True)


if __name__ == "__main__":
    unittest.main()
