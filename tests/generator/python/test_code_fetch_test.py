"""tools/code_fetch_test.py pads exactly the straight-line code of one generated function's namespace,
reads its verdict from the padding's cost, and writes a timing loop that compiles against a real
generated header (the timing itself is a measurement, docs/performance.md, not a test)."""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import mini_cheetah
import tools_module

TOOL = tools_module.load("code_fetch_test")

# Two functions as clang writes them: the namespace's (its symbol holds the namespace's name) and another.
ASSEMBLY = """\t.text
_ZN8rbdc_gen5robot6common18mass_matrix_0123ab11mass_matrixIdEEvPKT_PS3_:
\t.cfi_startproc
\tvmulsd\t%xmm1, %xmm0, %xmm0
.LBB0_1:
\tretq
.Lfunc_end0:
_Z5otherv:
\tvaddsd\t%xmm1, %xmm0, %xmm0
\tretq
.Lfunc_end1:
"""


class CodeFetchTest(unittest.TestCase):
    def test_only_the_namespaces_instructions_get_the_prefixes(self):
        lines = TOOL.padded(ASSEMBLY, "mass_matrix_0123ab", 2).splitlines()
        prefixed = [lines[i + 1] for i, line in enumerate(lines) if line == "\t.byte 0x3e,0x3e"]
        # its two instructions, not its label, directive or end, nor the other function's
        self.assertEqual(prefixed, ["\tvmulsd\t%xmm1, %xmm0, %xmm0", "\tretq"])
        self.assertEqual(TOOL.padded(ASSEMBLY, "mass_matrix_0123ab", 0), ASSEMBLY)

    def test_verdict_from_the_bytes_a_ns_the_padding_cost(self):
        self.assertEqual(TOOL.verdict(64), "yes")  # the decoders' rate: the code streams
        self.assertEqual(TOOL.verdict(40), "yes")
        self.assertEqual(TOOL.verdict(float("inf")), "no")  # no change: the op cache holds it
        self.assertEqual(TOOL.verdict(300), "no")
        self.assertEqual(TOOL.verdict(20), "more than its bytes")  # the padding pushed it out

    def test_the_timing_loop_compiles_against_a_generated_header(self):
        generated = Path(mini_cheetah.ROOT) / "generated"
        source = TOOL.driver(generated / "mini_cheetah" / "full" / "mass_matrix.hpp", "mini_cheetah", "full", "mass_matrix")
        self.assertIn("for (int i = 3; i < 7; ++i) q[s][i] /= n;", source)  # q's quaternion normalised
        self.assertIn("rbdc_gen::mini_cheetah::full::mass_matrix(q[s], M);", source)
        with tempfile.TemporaryDirectory() as scratch:
            path = os.path.join(scratch, "loop.cpp")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(source)
            subprocess.run(["c++", "-std=c++17", "-fsyntax-only", f"-I{generated}", "-I/usr/include/eigen3", path],
                           check=True)


if __name__ == "__main__":
    unittest.main()
