"""One robot and one scene through the whole compiler: rbdc-model → IR → traced functions → files."""
from dataclasses import dataclass, replace
from pathlib import Path

from ..frontend.actuators import with_actuator_mode
from ..errors import RbdcError
from ..frontend.layout import Layout
from ..frontend.model_tool import ModelRequest, load_robot
from ..backend.names import cpp_identifier
from ..backend.render import GeneratedFile, render_robot_scene
from ..frontend.scene import Scene, default_scene, load_scene
from ..passes.schedule import trace_scene


@dataclass(frozen=True)
class Compilation:
    robot: object            # rbdcgen.ir.Robot
    scene: Scene
    functions: list          # rbdcgen.trace Function objects
    robot_name: str          # C++ identifier: directory and namespace
    inputs: list[Path]       # the files the output depends on
    robot_inputs: list[Path]  # those of them that describe the robot (not the scene)


def resolve_base(scene: Scene, flag: str | None, robot, robot_path: Path) -> Scene:
    """The scene with its final base, decided once: the command line's flag overrides the scene file
    (that is the base asked of rbdc-model), and the loaded IR has the last word, since an IR file
    brings its own base; a flag the IR contradicts is an error."""
    ir_base = "floating" if robot.floating_base else "fixed"
    if flag and flag != ir_base:
        raise RbdcError(f"{robot_path}: the IR has a {ir_base} base, but a {flag} base was asked for")
    return scene if scene.base == ir_base else replace(scene, base=ir_base)


def compile_robot(robot_path: Path, scene_path: Path | None = None, topology: Path | None = None,
                  base: str | None = None, name: str | None = None, layout: Layout = None,
                  mimic: str = "couple", progress=None) -> Compilation:
    scene = load_scene(scene_path) if scene_path else default_scene()
    request = ModelRequest(robot=Path(robot_path), topology=Path(topology) if topology else None,
                           base=base or scene.base, locks=dict(scene.locked_joints), mimic=mimic)
    robot = with_actuator_mode(load_robot(request, layout), scene.actuators)
    scene = resolve_base(scene, base, robot, robot_path)
    robot_name = name or robot.name
    if not robot_name:
        raise RbdcError(f"{robot_path}: the robot has no name; give one with --name")
    inputs = request.inputs() + ([Path(scene_path)] if scene_path else [])
    return Compilation(robot=robot, scene=scene, functions=trace_scene(robot, scene, progress),
                       robot_name=cpp_identifier(robot_name), inputs=inputs, robot_inputs=request.inputs())


def render(compilation: Compilation, layout: Layout) -> list[GeneratedFile]:
    c = compilation
    return render_robot_scene(c.robot, c.scene, c.functions, c.robot_name, c.inputs, layout, c.robot_inputs)
