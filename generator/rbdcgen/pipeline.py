"""One robot and one scene through the whole compiler: rbdc-model → IR → traced functions → files."""
from dataclasses import dataclass
from pathlib import Path

from .errors import RbdcError
from .layout import Layout
from .model_tool import ModelRequest, load_robot
from .names import cpp_identifier
from .render import GeneratedFile, render_robot_scene
from .scene import Scene, default_scene, load_scene
from .trace import trace_scene


@dataclass(frozen=True)
class Compilation:
    robot: object            # rbdcgen.ir.Robot
    scene: Scene
    functions: list          # rbdcgen.trace Function objects
    robot_name: str          # C++ identifier: directory and namespace
    inputs: list[Path]       # the files the output depends on


def resolve_scene(scene_path: Path | None, base: str | None) -> Scene:
    """The scene from its file (or the default one), with the command line's base taking precedence."""
    scene = load_scene(scene_path) if scene_path else default_scene()
    if base and base != scene.base:
        scene = Scene(**{**scene.__dict__, "base": base})
    return scene


def compile_robot(robot_path: Path, scene_path: Path | None = None, topology: Path | None = None,
                  base: str | None = None, name: str | None = None, layout: Layout = None,
                  lock_mimic: bool = False) -> Compilation:
    scene = resolve_scene(scene_path, base)
    request = ModelRequest(robot=Path(robot_path), topology=Path(topology) if topology else None,
                           base=scene.base, locks=dict(scene.locked_joints), lock_mimic=lock_mimic)
    robot = load_robot(request, layout)
    ir_base = "floating" if robot.floating_base else "fixed"
    if base and base != ir_base:
        raise RbdcError(f"{robot_path}: the IR has a {ir_base} base, but a {base} base was asked for")
    if ir_base != scene.base:  # an IR file brings its own base
        scene = Scene(**{**scene.__dict__, "base": ir_base})
    robot_name = name or robot.name
    if not robot_name:
        raise RbdcError(f"{robot_path}: the robot has no name; give one with --name")
    inputs = request.inputs() + ([Path(scene_path)] if scene_path else [])
    return Compilation(robot=robot, scene=scene, functions=trace_scene(robot, scene),
                       robot_name=cpp_identifier(robot_name), inputs=inputs)


def render(compilation: Compilation, layout: Layout) -> list[GeneratedFile]:
    c = compilation
    return render_robot_scene(c.robot, c.scene, c.functions, c.robot_name, c.inputs, layout)
