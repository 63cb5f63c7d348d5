"""`rbdc verify`: generated code against the runtime on random and edge states.

Every robot of one call is generated into one directory and checked by one harness (rendered from
templates/verify_harness.cpp.j2), so many robots cost a single compile. The harness links the runtime
library; the compiler and external libraries come from rbdc-verify.json, written by CMake. RBDC_CXX
names another compiler for the harness (the tests take clang++, which compiles it at -O0 in about
half g++'s time).
"""
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ..errors import RbdcError
from ..passes.lane_functions import SCALAR
from ..frontend.layout import Layout
from ..backend.names import unique_identifiers
from .pipeline import compile_robot, render
from ..backend.render import template_environment
from ..frontend.scene import DERIVATIVES
from ..version import VERSION

HARNESS_TEMPLATE = "verify_harness.cpp.j2"


def cpp_string(text: str) -> str:
    """A C++ string literal (JSON's escapes are valid C++ escapes).

    >>> cpp_string('a "b"')
    '"a \\\\"b\\\\""'
    """
    return json.dumps(str(text))


def cpp_double(value: float) -> str:
    """A double literal that reads back exactly.

    >>> cpp_double(0.1), cpp_double(-2)
    ('0.1', '-2.0')
    """
    return repr(float(value))


def _robot_record(compilation, robot_path: Path, args) -> dict:
    scene, robot = compilation.scene, compilation.robot
    kind = "topology" if robot_path.suffix in (".yaml", ".yml") and not args.topology else "urdf"
    if robot_path.suffix == ".json":
        raise RbdcError(f"{robot_path}: verify needs the URDF or topology file (the runtime does not read IR)")
    return {
        "id": compilation.robot_name, "source": robot_path.as_posix(), "scene": scene.name,
        "namespace": f"rbdc_gen::{compilation.robot_name}::{scene.name}",
        "umbrella": f"{compilation.robot_name}/{scene.name}.hpp",
        "loader": {"kind": kind, "path": str(robot_path.resolve()), "floating_base": scene.base == "floating",
                   "mimic": args.mimic, "locks": list(scene.locked_joints),
                   "topology": str(args.topology.resolve()) if args.topology else ""},
        "gravity": list(scene.gravity_for(robot)),
        "feet": [foot.name for foot in scene.feet_for(robot)],
        "frames": [frame.name for frame in scene.frames_for(robot)],
        "contacts": [scene.feet_for(robot).index(foot) for foot in scene.contacts_for(robot)],
        "zero_inputs": list(scene.zero_inputs),
        "actuators": scene.actuators,
        "functions": [{"name": f.name, "inputs": [a.name for a in f.inputs], **_reference(f.name),
                       "outputs": [{"name": a.name, "rows": a.rows, "cols": a.cols} for a in f.outputs]}
                      for f in compilation.functions],
    }


def _reference(name: str) -> dict:
    """The function whose runtime call checks `name` (a lane function's scalar namesake), and
    whether it is a derivative (checked against the runtime's derivative members)."""
    reference = SCALAR.get(name, name)
    return {"reference": reference, "derivative": reference in DERIVATIVES}


def _toolchain(layout: Layout) -> dict:
    path = layout.verify_flags
    if not path.is_file():
        raise RbdcError(f"{path}: missing; configure the build (cmake -S . -B build) so that verify knows "
                        "its compiler and libraries")
    return json.loads(path.read_text())


def compile_harness(directory: Path, layout: Layout) -> Path:
    toolchain = _toolchain(layout)
    if not layout.runtime_library.is_file():
        raise RbdcError(f"{layout.runtime_library}: the runtime library is not built "
                        "(cmake --build build --target rbdc_runtime)")
    executable = directory / "harness"
    compiler = shlex.split(os.environ.get("RBDC_CXX") or toolchain["cxx"])
    command = [*compiler, "-std=c++17", "-O0", "-o", str(executable), str(directory / "harness.cpp"),
               "-I", str(directory / "generated"), "-I", str(layout.runtime_include)]
    command += [flag for d in toolchain["include_dirs"] for flag in ("-isystem", d)]
    command += [str(layout.runtime_library)] + toolchain["libraries"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        (directory / "compile.log").write_text(result.stderr)
        raise RbdcError(f"the verify harness did not compile ({directory / 'compile.log'}):\n"
                        + "\n".join(result.stderr.splitlines()[:30]))
    return executable


def _results(output: str) -> list[tuple[str, str, float, float, int]]:
    rows = []
    for line in output.splitlines():
        if line.startswith("RESULT "):
            _, robot, quantity, abs_error, rel_error, states = line.split()
            rows.append((robot, quantity, float(abs_error), float(rel_error), int(states)))
    return rows


def run(args, layout: Layout) -> int:
    paths = [Path(p) for p in args.robots]
    compilations, robot_paths = [], []
    if args.topology and len(paths) > 1:
        raise RbdcError("--topology applies to one robot; verify the robots one by one")
    for scene in [args.scene] + args.also_scene:
        for path, name in zip(paths, _batch_names(paths)):
            compilations.append(compile_robot(path, scene, args.topology, args.base, name, layout,
                                              mimic=args.mimic))
            robot_paths.append(path)
    directory = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="rbdc-verify-"))
    try:
        return build_and_run(robot_paths, compilations, directory, args, layout)
    finally:
        if not args.keep:
            shutil.rmtree(directory, ignore_errors=True)


def _batch_names(paths) -> list:
    """Distinct robot names within one harness (file stems; the robots' own names may repeat), or
    None for a single robot so that it keeps its own name."""
    return unique_identifiers([p.stem for p in paths]) if len(paths) > 1 else [None]


def build_and_run(paths, compilations, directory: Path, args, layout: Layout) -> int:
    generated = directory / "generated"
    for compilation in compilations:
        for f in render(compilation, layout):
            (generated / f.path).parent.mkdir(parents=True, exist_ok=True)
            (generated / f.path).write_text(f.text)
    environment = template_environment(layout)
    environment.filters.update(cpp_string=cpp_string, cpp_double=cpp_double)
    harness = environment.get_template(HARNESS_TEMPLATE).render(
        generator_version=VERSION,
        robots=[_robot_record(c, p, args) for c, p in zip(compilations, paths)])
    (directory / "harness.cpp").write_text(harness)
    start = time.monotonic()
    executable = compile_harness(directory, layout)
    compiled = time.monotonic()
    result = subprocess.run([str(executable), str(args.states), str(args.seed)], capture_output=True, text=True)
    if result.returncode != 0:
        raise RbdcError(f"the verify harness failed: {result.stderr.strip()}")
    rows = _results(result.stdout)
    print(f"{'robot':<20} {'quantity':<40} {'max abs error':>14} {'max rel error':>14} {'states':>7}")
    failed = 0
    for robot, quantity, abs_error, rel_error, states in rows:
        bad = not rel_error <= args.tolerance
        failed += bad
        print(f"{robot:<20} {quantity:<40} {abs_error:>14.3e} {rel_error:>14.3e} {states:>7}"
              + ("  FAIL" if bad else ""))
    print(f"{len(rows) - failed} passed, {failed} failed (relative tolerance {args.tolerance:g}; "
          f"compile {compiled - start:.1f} s, run {time.monotonic() - compiled:.1f} s)")
    if not rows:
        print("error: the harness reported no quantity", file=sys.stderr)
        return 1
    return 1 if failed else 0
