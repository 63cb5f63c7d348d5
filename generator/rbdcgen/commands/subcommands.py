"""What each `rbdc` subcommand does, given its parsed arguments (cli.py owns the parsing)."""
import json
import re
import subprocess
import sys
from pathlib import Path

from . import flops_report, verify
from ..errors import RbdcError
from ..frontend import model_tool
from ..frontend.layout import Layout
from ..frontend.model_tool import ModelRequest
from .pipeline import compile_robot, render
from ..backend.render import COMMON_DIR

_INCLUDE = re.compile(r'^#include "([^"]+)"', re.MULTILINE)
# Past this size a header's straight-line code takes g++ -O3 about 20 s or more (a 200-body chain's
# 4.2 MB forward dynamics: 17-20 s; docs/performance.md, "The mass matrix as a loop").
LARGE_HEADER_BYTES = 4_000_000


def large_header_warnings(files) -> list[str]:
    """One warning per generated file past LARGE_HEADER_BYTES: the user learns before compiling."""
    return [f"rbdc: warning: {f.path}: {len(f.text) / 1e6:.1f} MB of straight-line code; g++ -O3 may take "
            f"20 s or far more to compile it (leave the quantity out of the scene if it is not needed)"
            for f in files if len(f.text) > LARGE_HEADER_BYTES]


def _compile(args, layout: Layout):
    progress = _print_progress if getattr(args, "verbose", False) else None
    return compile_robot(args.robot, args.scene, args.topology, args.base, getattr(args, "name", None), layout,
                         mimic=args.mimic, progress=progress)


def _print_progress(function, seconds):
    """`generate --verbose`: one line per traced function, its form (the first clause of its schedule)."""
    form = function.schedule.split(":")[0].split(" (")[0] if function.schedule else "scalar tree"
    print(f"rbdc: {function.name}: {form}, {seconds:.1f} s", file=sys.stderr, flush=True)


def generate(args, layout: Layout) -> int:
    files = render(_compile(args, layout), layout)
    for warning in large_header_warnings(files):
        print(warning, file=sys.stderr)
    out = args.output
    if args.list_outputs:
        for f in files:
            print((out / f.path).as_posix())
        return 0
    changed = [f for f in files if not (out / f.path).is_file() or (out / f.path).read_text() != f.text]
    stale = _stale_files(files, out)
    if args.check:
        for f in changed:
            print(f"differs: {(out / f.path).as_posix()}")
        for path in stale:
            print(f"not generated any more: {path.as_posix()}")
        return 1 if changed or stale else 0
    for f in changed:
        if args.dry_run:
            print(f"would write {(out / f.path).as_posix()}")
        else:
            (out / f.path).parent.mkdir(parents=True, exist_ok=True)
            (out / f.path).write_text(f.text)
    for path in stale:
        if args.dry_run:
            print(f"would remove {path.as_posix()}")
        else:
            path.unlink()
    return 0


def _stale_files(files, out: Path) -> list[Path]:
    """Quantity headers left in this robot/scene directory by an earlier run with other quantities,
    and shared bodies in <robot>/common/ that no scene's header includes any more (this scene's new
    headers, the other scenes' headers on disk)."""
    umbrella = next(f for f in files if f.path.count("/") == 1 and not f.path.startswith("rbdc_gen/"))
    robot_dir = out / umbrella.path.split("/")[0]
    directory = out / umbrella.path.removesuffix(".hpp")
    wanted = {out / f.path for f in files}
    stale = sorted(p for p in directory.glob("*.hpp") if p not in wanted) if directory.is_dir() else []
    common = robot_dir / COMMON_DIR
    if not common.is_dir():
        return stale
    others = [p.read_text() for p in robot_dir.glob("*/*.hpp") if p.parent not in (directory, common)]
    included = {out / m for text in [f.text for f in files] + others for m in _INCLUDE.findall(text)}
    return stale + sorted(p for p in common.glob("*.hpp") if p not in included)


def flops(args, layout: Layout) -> int:
    compilation = _compile(args, layout)
    rows = flops_report.rows(compilation)
    print(json.dumps(flops_report.as_json(compilation, rows), indent=2, sort_keys=True) if args.json
          else flops_report.table(compilation, rows))
    return 0


def verify_command(args, layout: Layout) -> int:
    return verify.run(args, layout)


def evaluate(args, layout: Layout) -> int:
    if not layout.eval_tool.exists():
        raise RbdcError(f"{layout.eval_tool}: rbdc-eval is not built (cmake --build build --target rbdc-eval)")
    command = [str(layout.eval_tool), str(args.robot)]
    for option in ("q", "v", "a", "tau", "f", "contacts", "restitution", "kd"):
        if getattr(args, option):
            command += [f"--{option}", getattr(args, option)]
    if args.derivatives:
        command.append("--derivatives")
    if args.body_wrenches:
        command += ["--body-wrenches", str(args.body_wrenches)]
    for armature in args.armature:
        command += ["--armature", armature]
    if args.topology:
        command += ["--topology", str(args.topology)]
    if args.base:
        command.append(f"--{args.base}-base")
    if args.mimic != "couple":
        command.append(f"--{args.mimic}-mimic")
    result = subprocess.run(command, capture_output=True, text=True)
    sys.stdout.write(result.stdout)
    if result.returncode != 0:
        raise RbdcError("\n".join(line.removeprefix("error: ") for line in result.stderr.splitlines())
                        or f"rbdc-eval failed with exit code {result.returncode}")
    sys.stderr.write(result.stderr)
    return 0


def check(args, layout: Layout) -> int:
    request = ModelRequest(robot=args.robot, topology=args.topology, base=args.base, mimic=args.mimic)
    if not request.robot.is_file():
        raise RbdcError(f"{request.robot}: no such file")
    return model_tool.check(request, layout)


COMMANDS = {"generate": generate, "flops": flops, "verify": verify_command, "eval": evaluate, "check": check}
