#!/usr/bin/python3
"""Does a generated function's time follow its code's bytes? Builds a timing loop over the function
(its raw-pointer overload, 64 random states), once as compiled and once with every instruction of
its straight-line code (the functions of its namespace rbdc_gen::ROBOT::common::FUNCTION_HASH)
behind PAD ignored segment prefixes: the same instructions, more bytes. Times both from fresh
copies of each binary, in turn, and prints the added bytes per added ns. Code the core runs from its
op cache costs nothing more (the prefixes are gone once decoded); code that streams through the
decoders, about 16 bytes a cycle on Zen 5 (64 a ns: tools/machine_peak.cpp), costs about one ns
per 64 bytes more, and then its time cannot drop below its bytes over that rate
(docs/performance.md, "Code that streams"). Padding that costs far more than its own bytes pushed
code a cache held out of it: that function is at the edge, and fewer bytes would speed it up.

Usage: tools/code_fetch_test.py GENERATED ROBOT SCENE FUNCTION [FUNCTION ...]
                                [--pad N] [--copies N] [--cxx COMPILER]
  GENERATED  the directory holding ROBOT/SCENE/FUNCTION.hpp (`./rbdc generate` output)
  --pad      ignored prefixes per instruction (default 2)
  --copies   fresh copies of each binary, run in turn (default 5; the minimum counts)
  --cxx      the compiler (default clang++-14, the peer harness's), with -O3 -march=native
"""
import argparse
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from instruction_rates import STREAMED_BYTES_PER_NS, code_namespace, code_sizes
PARAM = re.compile(r"^/// @param (\w+) (in|out) +(\d+)x(\d+): (.*)$", re.M)

DRIVER = """#include "{robot}/{scene}/{function}.hpp"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
int main() {{
  std::mt19937 random(1);
  std::uniform_real_distribution<double> uniform(-1, 1);
{declarations}
  for (int s = 0; s < 64; ++s) {{
{fills}
  }}
  volatile double sink = 0;
  double best = 1e300;
  for (int repetition = 0; repetition < 60; ++repetition) {{
    const auto start = std::chrono::steady_clock::now();
    for (int n = 0; n < 2000; ++n) {{
      const int s = n & 63;
      rbdc_gen::{robot}::{scene}::{function}({arguments});
      sink = sink + {first_out}[s % {first_out_size}];
    }}
    best = std::fmin(best, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / 2000);
  }}
  std::printf("%.1f\\n", best);
}}
"""


def driver(header, robot, scene, function):
    """The timing loop's source: inputs random in [-1, 1] (a quaternion at q[3:7] normalised),
    outputs written to one array each."""
    params = PARAM.findall(header.read_text())
    declarations, fills, arguments = [], [], []
    for name, direction, rows, columns, description in params:
        size = int(rows) * int(columns)
        if direction == "in":
            declarations.append(f"  static double {name}[64][{size}];")
            fills.append(f"    for (auto& x : {name}[s]) x = uniform(random);")
            if "quaternion" in description:
                fills.append(f"    {{ const double n = std::sqrt({name}[s][3] * {name}[s][3] + {name}[s][4] * {name}[s][4] + "
                             f"{name}[s][5] * {name}[s][5] + {name}[s][6] * {name}[s][6]); "
                             f"for (int i = 3; i < 7; ++i) {name}[s][i] /= n; }}")
            arguments.append(f"{name}[s]")
        else:
            declarations.append(f"  alignas(64) static double {name}[{size}];")
            arguments.append(name)
    first_out = next((name, int(r) * int(c)) for name, d, r, c, _ in params if d == "out")
    return DRIVER.format(robot=robot, scene=scene, function=function, declarations="\n".join(declarations),
                         fills="\n".join(fills), arguments=", ".join(arguments),
                         first_out=first_out[0], first_out_size=first_out[1])


def padded(assembly, namespace, pad):
    """The assembly with `pad` segment prefixes (0x3e, ignored in 64-bit mode) before each
    instruction of the functions whose symbol holds the namespace's name."""
    lines, inside = [], False
    for line in assembly.splitlines():
        if re.match(r"^_Z\S*:", line):
            inside = namespace in line
        elif line.startswith(".Lfunc_end"):
            inside = False
        if inside and pad and re.match(r"^\t[a-z]", line):
            lines.append("\t.byte " + ",".join(["0x3e"] * pad))
        lines.append(line)
    return "\n".join(lines) + "\n"


def timed(binary, work):
    """ns per call from a fresh copy of the binary (a copy gets its own physical pages)."""
    path = work / f"{binary.name}.copy"
    shutil.copy(binary, path)
    return float(subprocess.run(["taskset", "-c", "1", str(path)], capture_output=True, text=True,
                                check=True).stdout)


def verdict(rate):
    """Whether the code streams, from the bytes a ns its padding cost: about the streaming rate
    (within a factor 2) when it streams, far more when the op cache holds it even padded, far less
    when the padding cost more than streaming its own bytes: code that a cache held (the op cache,
    or level 2 for the largest) left it, so it was held, or partly, and fewer bytes would pay."""
    if rate > 2 * STREAMED_BYTES_PER_NS:
        return "no"
    return "yes" if rate >= STREAMED_BYTES_PER_NS / 2 else "more than its bytes"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("generated", type=Path)
    parser.add_argument("robot")
    parser.add_argument("scene")
    parser.add_argument("functions", nargs="+")
    parser.add_argument("--pad", type=int, default=2)
    parser.add_argument("--copies", type=int, default=5)
    parser.add_argument("--cxx", default="clang++-14")
    args = parser.parse_args()
    print("| function | KB | ns | KB padded | ns padded | bytes a ns added | streams |")
    print("|---|---:|---:|---:|---:|---:|---|")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for function in args.functions:
            header = args.generated / args.robot / args.scene / f"{function}.hpp"
            namespace = code_namespace(header)
            source = work / f"{function}.cpp"
            source.write_text(driver(header, args.robot, args.scene, function))
            subprocess.run([args.cxx, "-std=c++17", "-O3", "-march=native", "-DNDEBUG", f"-I{args.generated}",
                            "-I/usr/include/eigen3", "-S", str(source), "-o", str(work / "plain.s")], check=True)
            assembly = (work / "plain.s").read_text()
            binaries = []
            for pad in (0, args.pad):
                # the mangled symbols hold the namespace's last name (FUNCTION_HASH)
                (work / f"{function}_{pad}.s").write_text(padded(assembly, namespace.rsplit("::", 1)[1], pad))
                binaries.append(work / f"{function}_{pad}")
                subprocess.run([args.cxx, str(work / f"{function}_{pad}.s"), "-o", str(binaries[-1])], check=True)
            sizes = [code_sizes([f"{args.robot}={binary}"])[args.robot][namespace] for binary in binaries]
            times = [1e300, 1e300]
            for _ in range(args.copies):  # the two binaries in turn
                times = [min(t, timed(binary, work)) for t, binary in zip(times, binaries)]
            added = times[1] - times[0]
            # under 3 % of the call is within the copies' spread: nothing measured
            rate = (sizes[1] - sizes[0]) / added if added > 0.03 * times[0] else float("inf")
            print("| %s | %.1f | %.0f | %.1f | %.0f | %s | %s |" % (
                function, sizes[0] / 1024, times[0], sizes[1] / 1024, times[1],
                "%.0f" % rate if rate != float("inf") else "∞",
                verdict(rate)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
