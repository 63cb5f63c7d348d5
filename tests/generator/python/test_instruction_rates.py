"""tools/instruction_rates.py reads a function's counted instructions from its header (the schedule
line, else the operation table) and turns a measured time into a rate: the rate the target would
need follows from the peer's time, the most the code could sustain from its multiplications' share."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

import mini_cheetah

TOOL = os.path.join(mini_cheetah.ROOT, "tools", "instruction_rates.py")
# Two headers' doc comments as the generator writes them: a schedule line wrapped over two lines,
# and an operation table alone.
HEADERS = {
    "mass_matrix": ("/// operations  mul  add  div  sqrt  trig  neg  total\n"
                    "///             388  366    0     0    24   27    805\n"
                    "/// schedule: limb lanes (the 4 isomorphic limbs in SIMD lanes, the trunk scalar): 217 arithmetic\n"
                    "///   instructions, scalar tree 781, looped CRBA 2252 (cost 3137)\n"),
    "inverse_dynamics": ("/// operations  mul  add  div  sqrt  trig  neg  total\n"
                         "///             475  365    0     0    12    1    853\n"),
}


# The harness's summary rows: plain, and as its summary marks them (thousands separators, the ratio bold).
SUMMARY = ("| robot | crba → mass_matrix | 500 / 547.5 | 70 / 73 | 7.50× |\n"
           "| robot | rnea → inverse_dynamics | 900.0 / 1,000.0 | 90.0 / 100.0 | **10.00×** | 21 / 21 |\n")


def run_tool(scratch, *options, headers=None):
    """The tool's output lines on `headers` (default HEADERS) and SUMMARY written into `scratch`,
    clock 3.65 GHz."""
    os.makedirs(os.path.join(scratch, "robot", "full"))
    for name, text in (headers or HEADERS).items():
        with open(os.path.join(scratch, "robot", "full", name + ".hpp"), "w", encoding="utf-8") as handle:
            handle.write(text)
    summary = os.path.join(scratch, "summary.md")
    with open(summary, "w", encoding="utf-8") as handle:
        handle.write(SUMMARY)
    return subprocess.run([sys.executable, TOOL, summary, scratch, "3.65", *options], check=True,
                          capture_output=True, text=True).stdout.splitlines()


class InstructionRatesTest(unittest.TestCase):
    def test_rates_from_the_headers_and_the_times(self):
        with tempfile.TemporaryDirectory() as scratch:
            rows = run_tool(scratch)[2:]
        # 853 operations in 100 ns = 365 cycles; M's 217 instructions in 73 ns = 266.45 cycles, and
        # 10x the peer's 547.5 ns, 54.75 ns, is 199.84 cycles; multiplications 475 of 840 (two FMA
        # pipes: 2 / 0.5655 = 3.54 a cycle) and 388 of 754 (3.89), both under the 4.05 peak
        self.assertEqual(rows, ["| robot | ID | 100 | 853 | 2.34 | 10.00× | 10× | met | 57 % | 3.54 |",
                                "| robot | M | 73 | 217 | 0.81 | 7.50× | 10× | 1.09 | 51 % | 3.89 |"])

    def test_critical_paths_bound_the_ratio_from_the_latency_side(self):
        with tempfile.TemporaryDirectory() as scratch:
            flops = os.path.join(scratch, "flops.json")
            with open(flops, "w", encoding="utf-8") as handle:
                json.dump({"functions": {
                    "mass_matrix": {"critical_path": {"cycles": 365, "traced_part_only": False}},
                    "inverse_dynamics": {"critical_path": {"cycles": 730, "traced_part_only": True}}}}, handle)
            rows = run_tool(scratch, "--paths", "robot=" + flops)
        self.assertTrue(rows[0].endswith("| critical path ns | most by latency |"))
        # 730 cycles at 3.65 GHz: 200 ns, the peer's 1 000 over it 5x (a looped form: +); M's 365: 100 ns
        self.assertTrue(rows[2].endswith("| 200+ | 5.0×+ |"), rows[2])
        self.assertTrue(rows[3].endswith("| 100 | 5.5× |"), rows[3])

    def test_code_bytes_bound_the_ratio_when_the_code_streams(self):
        with tempfile.TemporaryDirectory() as scratch:
            # M's header includes its code's file; the binary holds 6 400 one-byte no-ops and a ret in
            # that file's namespace (a naked function: no prologue), and 3 201 bytes outside it
            headers = dict(HEADERS, mass_matrix=HEADERS["mass_matrix"] + '#include "robot/common/mass_matrix_0123abcd.hpp"\n')
            source = os.path.join(scratch, "code.cpp")
            with open(source, "w", encoding="utf-8") as handle:
                handle.write('namespace rbdc_gen::robot::common::mass_matrix_0123abcd {\n'
                             '__attribute__((naked)) void mass_matrix() { asm(".rept 6400\\nnop\\n.endr\\nret"); }\n}\n'
                             '__attribute__((naked)) void elsewhere() { asm(".rept 3200\\nnop\\n.endr\\nret"); }\n')
            binary = os.path.join(scratch, "code.o")
            subprocess.run(["c++", "-c", source, "-o", binary], check=True)
            rows = run_tool(scratch, "--code", "robot=" + binary, headers=headers)
        self.assertTrue(rows[0].endswith("| code KB | most if it streams |"))
        # 6 401 bytes at 64 a ns: 100.0 ns, the peer's 547.5 over it 5.5x; ID's code is not in the binary
        self.assertTrue(rows[3].endswith("| 6.3 | 5.5× |"), rows[3])
        self.assertTrue(rows[2].endswith("| – | – |"), rows[2])


if __name__ == "__main__":
    unittest.main()
