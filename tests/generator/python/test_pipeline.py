"""The scene's base is decided once (pipeline.resolve_base): the command line's flag overrides the
scene file, the loaded IR has the last word, and a flag the IR contradicts is an error. `generate`
warns about a header too large to compile quickly."""

import os
import unittest

from numeric_check import DATA
from rbdcgen.backend.render import GeneratedFile
from rbdcgen.commands.subcommands import LARGE_HEADER_BYTES, large_header_warnings
from rbdcgen.errors import RbdcError
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.layout import find_layout
from rbdcgen.commands.pipeline import compile_robot, resolve_base
from rbdcgen.frontend.scene import Scene, default_scene

FIXED = os.path.join(DATA, "tiny_fixed.json")
FLOATING = os.path.join(DATA, "tiny_floating.json")


class BaseResolution(unittest.TestCase):
    def test_the_ir_decides_when_no_flag_is_given(self):
        scene = resolve_base(default_scene(), None, load_ir(FIXED), FIXED)
        self.assertEqual(scene.base, "fixed")
        self.assertEqual(scene.name, "full")
        floating = Scene(name="s", base="fixed")
        self.assertEqual(resolve_base(floating, None, load_ir(FLOATING), FLOATING).base, "floating")

    def test_an_agreeing_flag_keeps_the_scene(self):
        scene = Scene(name="s", base="floating")
        self.assertIs(resolve_base(scene, "floating", load_ir(FLOATING), FLOATING), scene)

    def test_a_flag_the_ir_contradicts_is_an_error(self):
        with self.assertRaises(RbdcError) as caught:
            resolve_base(default_scene(), "floating", load_ir(FIXED), FIXED)
        self.assertIn("fixed base, but a floating base was asked for", str(caught.exception))

    def test_compile_robot_resolves_an_ir_file_once(self):
        compilation = compile_robot(FIXED, layout=find_layout())
        self.assertEqual(compilation.scene.base, "fixed")
        self.assertNotIn("osc_open_chain", [f.name for f in compilation.functions])
        self.assertEqual(compilation.robot_inputs, compilation.inputs)  # no scene file
        with self.assertRaises(RbdcError):
            compile_robot(FIXED, base="floating", layout=find_layout())


if __name__ == "__main__":
    unittest.main()


class LargeHeaders(unittest.TestCase):
    def test_a_header_past_the_limit_is_named_in_a_warning(self):
        files = [GeneratedFile("r/common/big.hpp", "x" * (LARGE_HEADER_BYTES + 1)),
                 GeneratedFile("r/common/small.hpp", "x" * LARGE_HEADER_BYTES)]
        warnings = large_header_warnings(files)
        self.assertEqual(len(warnings), 1)
        self.assertIn("r/common/big.hpp: 4.0 MB of straight-line code", warnings[0])
