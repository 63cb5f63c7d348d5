"""Runs the ./rbdc launcher as a user would, for the product tests (environment from CTest)."""
import os
import shlex
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
LAUNCHER = ROOT / "rbdc"
MINI_CHEETAH = ROOT / "robots" / "mini_cheetah.urdf"
SCENES = ROOT / "scenes"
DATA = Path(__file__).resolve().parent / "data"
# The compiler of the tests' own drivers: RBDC_CXX as for the verify harness (CTest sets clang++).
CXX = shlex.split(os.environ.get("RBDC_CXX") or os.environ.get("CXX") or "c++")


def run_rbdc(*args, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([str(LAUNCHER), *map(str, args)], capture_output=True, text=True,
                          cwd=cwd or ROOT, env=os.environ.copy())
