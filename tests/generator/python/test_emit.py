"""Emitted statements: deterministic text, every output entry written exactly once, joint sin/cos
first in one block and named by joint, constants printed exactly and short, temporaries declared
before use, phase markers in the algorithm's order."""

import os
import re
import subprocess
import sys
import unittest

from numeric_check import DATA, HERE, operator_count
from rbdcgen.graph import expr as ex
from rbdcgen.backend.emit import MAX_INLINE_OPS, emit_body, format_constant
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene
from rbdcgen.passes.trace import Argument, Function, trace_function
from rbdcgen.passes.schedule import trace_scene

ROBOT = load_ir(os.path.join(DATA, "tiny_floating.json"))

SCRIPT = """
import sys
sys.path.insert(0, %r)
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene
from rbdcgen.passes.schedule import trace_scene
from rbdcgen.backend.emit import emit_body
robot = load_ir(%r)
for fn in trace_scene(robot, default_scene()):
    print(fn.name)
    print("\\n".join(emit_body(fn)))
"""


class Emission(unittest.TestCase):
    def test_same_input_gives_byte_identical_text_across_processes(self):
        generator = os.path.join(HERE, "..", "..", "..", "generator")
        script = SCRIPT % (generator, os.path.join(DATA, "tiny_floating.json"))
        runs = [subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                               check=True, env={**os.environ, "PYTHONHASHSEED": seed}).stdout
                for seed in ("1", "2")]
        self.assertEqual(runs[0], runs[1])
        self.assertIn("mass_matrix", runs[0])

    def test_each_output_entry_written_once_and_temporaries_defined_before_use(self):
        for fn in trace_scene(ROBOT, default_scene()):
            lines = emit_body(fn)
            defined = set()
            for line in (l for l in lines if not l.startswith("//")):
                declared = re.match(r"Scalar (\w+) = (.*);$", line)
                used = set(re.findall(r"\b(t\d+|sin_q_\d+|cos_q_\d+)\b",
                                      declared.group(2) if declared else line.split("=", 1)[1]))
                self.assertLessEqual(used, defined, "%s: %s" % (fn.name, line))
                if declared:
                    defined.add(declared.group(1))
            for arg in fn.outputs:
                writes = [l for l in lines if l.startswith(arg.name + "[")]
                indices = sorted(int(l[len(arg.name) + 1:l.index("]")]) for l in writes)
                self.assertEqual(indices, list(range(arg.size)), fn.name + " " + arg.name)

    def test_inlined_expressions_stay_short(self):
        for fn in trace_scene(ROBOT, default_scene()):
            for line in emit_body(fn):
                self.assertLessEqual(operator_count(line), MAX_INLINE_OPS, line)

    def test_joint_trig_comes_first_and_once(self):
        fn = trace_function(ROBOT, default_scene(), "inverse_dynamics")
        lines = emit_body(fn)
        # two revolute joints; the prismatic one has no angle
        self.assertEqual(lines[:3], ["// sines and cosines of the joint angles",
                                     "Scalar joint_angle[2] = {q[7], q[8]};",
                                     "auto joint_trig = joint_sincos(joint_angle);"])
        trig = [l for l in lines if "joint_trig." in l]
        self.assertEqual(lines[3:3 + len(trig)], trig)
        self.assertEqual(len(trig), 4)
        self.assertEqual(trig[0], "Scalar sin_q_7 = joint_trig.sin[0];")

    def test_joint_trig_is_named_by_joint(self):
        fn = trace_function(ROBOT, default_scene(), "inverse_dynamics")
        lines = emit_body(fn, {("q", 7): "hip", ("q", 8): "knee"})
        self.assertIn("Scalar sin_hip = joint_trig.sin[0];", lines)
        self.assertIn("Scalar cos_knee = joint_trig.cos[1];", lines)
        self.assertFalse([l for l in lines if "sin_q_" in l or "cos_q_" in l])

    def test_markers_follow_the_passes_of_the_algorithm(self):
        lines = emit_body(trace_function(ROBOT, default_scene(), "mass_matrix"))
        markers = [l for l in lines if l.startswith("//")]
        # CRBA's inward pass from the last body to the first, each body once, then the outputs.
        crba = "// inward pass, composite inertias (CRBA): body "
        self.assertEqual(markers, ["// sines and cosines of the joint angles", crba + "3 slider",
                                   crba + "2 lower", crba + "1 upper", "// outputs"])
        # each entry once, stored right after the last temporary it reads (not all at the end)
        stores = [i for i, l in enumerate(lines) if l.startswith("M[")]
        n = ROBOT.nv
        self.assertEqual(sorted(int(lines[i][2:lines[i].index("]")]) for i in stores), list(range(n * n)))
        self.assertLess(stores[0], lines.index("// outputs"))
        for i in stores:
            read = [int(t) for t in re.findall(r"\bt(\d+)\b", lines[i])]
            previous = next(lines[j] for j in range(i - 1, -1, -1) if not lines[j].startswith("//"))
            if read:
                self.assertTrue(previous.startswith("Scalar t%d = " % max(read))
                                or previous.startswith("M["), (previous, lines[i]))

    def test_constants_are_exact_and_symmetric_entries_mirrored(self):
        self.assertEqual(format_constant(0.209), "Scalar(0.209)")
        self.assertEqual(format_constant(-1.0), "Scalar(-1)")
        for value in (0.1 + 0.2, 1 / 3, 6.0000000000000002e-06, -0.013375999999999999, 1e300):
            text = format_constant(value)
            self.assertEqual(float(text[len("Scalar("):-1]), value, text)
        fn = trace_function(ROBOT, default_scene(), "mass_matrix")
        M = fn.values["M"]
        n = ROBOT.nv
        for r in range(n):
            for c in range(n):
                self.assertIs(M[c * n + r], M[r * n + c])

    def test_structural_zeros_are_written(self):
        with ex.Graph() as graph:
            out = (ex.symbol("q", 0) * 2.0, ex.const(0.0))
        fn = Function("f", "", (Argument("q", 1, 1, ""),), (Argument("y", 2, 1, ""),),
                      {"y": out}, graph)
        self.assertEqual(emit_body(fn), ["// outputs", "y[0] = Scalar(2) * q[0];", "y[1] = Scalar(0);"])

    def test_a_negative_constant_operand_flips_the_operator(self):
        with ex.Graph() as graph:
            x = ex.symbol("q", 0)
            out = (ex.sub(x, ex.const(-0.5)), ex.add(ex.const(-0.25), x), ex.sub(ex.const(-2.0), x))
        fn = Function("f", "", (Argument("q", 1, 1, ""),), (Argument("y", 3, 1, ""),),
                      {"y": out}, graph)
        self.assertEqual(emit_body(fn)[1:], ["y[0] = q[0] + Scalar(0.5);", "y[1] = q[0] - Scalar(0.25);",
                                             "y[2] = Scalar(-2) - q[0];"])


if __name__ == "__main__":
    unittest.main()
