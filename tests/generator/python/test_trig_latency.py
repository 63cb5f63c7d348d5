"""tools/trig_latency.py finds joint_sincos's double overload in the generated support.hpp it patches,
and its driver compiles, as generated against a bundled fixed-base arm and with the stand-in sines
against a floating-base quadruped. The timing itself is a measurement (docs/performance.md, "The sines'
latency in series"), not a test."""

import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

import mini_cheetah
import tools_module

TOOL = tools_module.load("trig_latency")
GENERATED = Path(mini_cheetah.ROOT) / "generated"


class TrigLatencyTest(unittest.TestCase):
    def test_the_stand_in_goes_first_in_the_double_overload(self):
        text = TOOL.with_stand_in((GENERATED / "rbdc_gen" / "support.hpp").read_text())
        self.assertEqual(text.count("#ifdef RBDC_TRIG_STAND_IN"), 1)
        self.assertLess(text.index(TOOL.OPENING), text.index("#ifdef RBDC_TRIG_STAND_IN"))

    def test_an_overload_that_moved_is_an_error(self):
        with self.assertRaises(SystemExit):
            TOOL.with_stand_in("#pragma once\n// joint_sincos as it no longer reads\n")

    def test_the_driver_compiles_both_ways(self):
        with tempfile.TemporaryDirectory() as scratch:
            tree = Path(scratch) / "gen"
            shutil.copytree(GENERATED / "rbdc_gen", tree / "rbdc_gen")
            support = tree / "rbdc_gen" / "support.hpp"
            support.write_text(TOOL.with_stand_in(support.read_text()))
            # each build once, on a robot of each base (a compile each: about 1.5 s)
            for robot, floating, flags in (("arm7", False, []), ("mini_cheetah", True, ["-DRBDC_TRIG_STAND_IN"])):
                source = Path(scratch) / f"{robot}.cpp"
                source.write_text(TOOL.driver(robot, floating))
                subprocess.run(["c++", "-std=c++17", "-fsyntax-only", "-march=x86-64-v2", *flags, f"-I{tree}",
                                f"-I{GENERATED}", "-I/usr/include/eigen3", str(source)], check=True)


if __name__ == "__main__":
    unittest.main()
