"""What the tools that time a copy of a generated tree share (tools/loop_phases.py,
tools/trig_latency.py): their command line's common part, and the driver's build with the peer
harness's flags (bench/peer/README.md), so that their times read as the harness's do."""
import argparse
import subprocess
from pathlib import Path


def parser(doc):
    """GENERATED ROBOT [--floating] [--runs N] [--cxx CXX]; each tool adds its own options."""
    arguments = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    arguments.add_argument("generated", type=Path)
    arguments.add_argument("robot")
    arguments.add_argument("--floating", action="store_true")
    arguments.add_argument("--runs", type=int, default=5)
    arguments.add_argument("--cxx", default="clang++-14")
    return arguments


def build(cxx, tree, source, binary, flags=()):
    """Compiles the driver `source` against the generated tree `tree` into `binary`."""
    subprocess.run([cxx, "-std=c++17", "-O3", "-march=native", "-DNDEBUG", *flags, "-I/usr/include/eigen3",
                    f"-I{tree}", str(source), "-o", str(binary)], check=True)
