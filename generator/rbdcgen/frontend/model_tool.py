"""Front end: runs the C++ tool rbdc-model, the one place that parses, validates and numbers a robot,
and reads its IR (docs/ir.md). An IR JSON file is accepted as input directly."""
import json
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import RbdcError
from .ir import Robot, load_ir
from .layout import Layout


@dataclass(frozen=True)
class ModelRequest:
    """What to ask rbdc-model for: the robot file and the options a scene or the command line set."""
    robot: Path
    topology: Path | None = None
    base: str | None = None                      # 'floating', 'fixed' or None for the file's own
    locks: dict[str, float] = field(default_factory=dict)
    mimic: str = "couple"                        # couple | lock | independent (docs/model.md)

    def inputs(self) -> list[Path]:
        """The files the IR depends on, for banners (hashes) and build-system dependencies."""
        return [self.robot] + ([self.topology] if self.topology else [])


def model_command(request: ModelRequest, layout: Layout) -> list[str]:
    command = [str(layout.model_tool), str(request.robot)]
    if request.topology:
        command += ["--topology", str(request.topology)]
    if request.base:
        command.append(f"--{request.base}-base")
    if request.mimic != "couple":
        command.append(f"--{request.mimic}-mimic")
    for name, value in sorted(request.locks.items()):
        command += ["--lock", f"{name}={value!r}"]
    return command


def check(request: ModelRequest, layout: Layout) -> int:
    """`rbdc check`: rbdc-model's lint report (every warning and the refusal with file:line, then the
    topology) on stdout; its exit code, 0 unless the robot is refused."""
    if not layout.model_tool.exists():
        raise RbdcError(f"{layout.model_tool}: rbdc-model is not built (cmake --build build --target rbdc-model)")
    result = subprocess.run(model_command(request, layout) + ["--check"], capture_output=True, text=True)
    sys.stdout.write(result.stdout)
    sys.stderr.write(result.stderr)
    return result.returncode


def load_robot(request: ModelRequest, layout: Layout) -> Robot:
    """The IR for the request; raises RbdcError with rbdc-model's own message on bad input (IRError
    naming the file for a malformed IR file)."""
    if not request.robot.is_file():
        raise RbdcError(f"{request.robot}: no such file")
    if request.robot.suffix == ".json":
        if request.topology or request.locks or request.mimic != "couple":
            raise RbdcError(f"{request.robot}: an IR file is already numbered; --topology, the mimic "
                            "options and locked joints apply only to URDF or topology input")
        return load_ir(request.robot)
    if not layout.model_tool.exists():
        raise RbdcError(f"{layout.model_tool}: rbdc-model is not built (cmake --build build --target rbdc-model)")
    result = subprocess.run(model_command(request, layout), capture_output=True, text=True)
    for line in result.stderr.splitlines():
        if line.startswith("warning:"):
            print(f"rbdc: {line}", file=sys.stderr)
    if result.returncode != 0:
        errors = [line for line in result.stderr.splitlines() if not line.startswith("warning:")]
        message = "\n".join(line.removeprefix("error: ") for line in errors) or \
            f"rbdc-model failed with exit code {result.returncode}"
        raise RbdcError(message)
    return load_ir(json.loads(result.stdout))

