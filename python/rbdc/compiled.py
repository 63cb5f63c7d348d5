"""rbdc.compile: the generator's code for one robot and scene as a Python extension module, built once
per content and cached per user (docs/python.md).

The cache key is a hash of everything the module depends on: the robot, topology and scene files'
bytes, the options, the generator's and the bindings' sources, the compiler command and the Python
ABI. A hit loads the module without running the generator. A miss generates and compiles into a
temporary directory and renames it into place under a file lock, so concurrent calls (threads,
processes, Dask workers on one machine) build once and never see a half-written entry.
"""
import concurrent.futures
import fcntl
import hashlib
import importlib.machinery
import importlib.util
import os
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import _home

KEY_VERSION = "rbdc-compile-1"
# -march=native as ./run and bench/report build; the generated code is written for -O3.
DEFAULT_FLAGS = ("-O3", "-march=native", "-DNDEBUG", "-std=c++17", "-fPIC", "-fvisibility=hidden")


@dataclass(frozen=True)
class Target:
    """What to compile, as plain data (picklable, so Dask can ship it to workers): the input files'
    bytes travel with it, so a worker on another machine needs rbdc but not the files."""
    robot: bytes
    robot_name: str          # file name, for the generator (URDF or topology .yaml)
    scene: bytes
    scene_name: str
    topology: bytes | None = None
    base: str | None = None  # None: the scene's (floating unless the scene says fixed)
    mimic: str = "couple"
    float32: bool = False    # also the float32 instantiation (an all-float32 batch computes in float32)

    @classmethod
    def from_files(cls, robot, scene="full", topology=None, base=None, mimic="couple", float32=False):
        robot, scene_path = Path(robot), _scene_path(scene)
        for path, what in ((robot, "robot"), (scene_path, "scene"), (topology, "topology")):
            if path is not None and not Path(path).is_file():
                raise FileNotFoundError(f"rbdc.compile: {what} file {path} does not exist")
        if base not in (None, "floating", "fixed"):
            raise ValueError(f"rbdc.compile: base must be 'floating' or 'fixed', not {base!r}")
        if mimic not in ("couple", "lock", "independent"):
            raise ValueError(f"rbdc.compile: mimic must be 'couple', 'lock' or 'independent', not {mimic!r}")
        return cls(robot=robot.read_bytes(), robot_name=robot.name, scene=scene_path.read_bytes(),
                   scene_name=scene_path.name, topology=Path(topology).read_bytes() if topology else None,
                   base=base, mimic=mimic, float32=bool(float32))


def _scene_path(scene) -> Path:
    """A scene file, or the name of a bundled one (scenes/<name>.yaml)."""
    path = Path(scene)
    if path.suffix in (".yaml", ".yml") or path.is_file():
        return path
    root = _home.source_root()
    return (root / "scenes" if root else _home.share_dir() / "scenes") / f"{scene}.yaml"


def _compiler() -> list[str]:
    return shlex.split(os.environ.get("RBDC_CXX") or os.environ.get("CXX") or "c++")


def _include_dirs() -> list[str]:
    import pybind11  # Debian python3-pybind11
    return [str(_home.NATIVE_INCLUDE), pybind11.get_include(), sysconfig.get_paths()["include"], "/usr/include/eigen3"]


def _flags() -> list[str]:
    return [*DEFAULT_FLAGS, *shlex.split(os.environ.get("RBDC_CXXFLAGS", ""))]


def _sources_digest(digest) -> None:
    """The generator, its templates, the loader (rbdc-model) and the bindings: their sources' bytes."""
    generator = _home.generator_dir()
    root = generator.parent
    trees = [(generator / "rbdcgen", "*.py"), (root / "templates", "*.j2"), (_home.NATIVE_INCLUDE, "*.hpp"),
             (root / "runtime", "*.[ch]pp")]
    for folder, pattern in trees:
        for path in sorted(folder.rglob(pattern)):
            digest.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes())


def cache_key(target: Target) -> str:
    import pybind11
    digest = hashlib.sha256(KEY_VERSION.encode())
    for part in (target.robot, target.robot_name.encode(), target.scene, target.topology or b"-",
                 str(target.base).encode(), target.mimic.encode(), str(target.float32).encode(), " ".join(_compiler() + _flags()).encode(),
                 sysconfig.get_config_var("EXT_SUFFIX").encode(), pybind11.__version__.encode()):
        digest.update(len(part).to_bytes(8, "little") + part)
    _sources_digest(digest)
    return digest.hexdigest()[:32]


def _module_file(entry: Path):
    found = sorted(entry.glob("rbdc_compiled_*" + sysconfig.get_config_var("EXT_SUFFIX")))
    return found[0] if found else None


def _load(entry: Path):
    path = _module_file(entry)
    name = path.name.split(".")[0]
    if name in sys.modules:
        return sys.modules[name]
    loader = importlib.machinery.ExtensionFileLoader(name, str(path))
    module = importlib.util.module_from_spec(importlib.util.spec_from_file_location(name, path, loader=loader))
    loader.exec_module(module)
    module.cache_entry = entry
    sys.modules[name] = module
    return module


def _generate(target: Target, work: Path, module_name: str) -> list[Path]:
    """Writes the inputs, the generated headers and the module's sources into `work`; returns the sources."""
    sys.path.insert(0, str(_home.generator_dir()))
    try:
        from rbdcgen.backend.python_module import render_python_module
        from rbdcgen.commands.pipeline import compile_robot, render
        from rbdcgen.frontend.layout import find_layout
    finally:
        sys.path.pop(0)
    inputs = work / "inputs"
    inputs.mkdir()
    robot = inputs / target.robot_name
    robot.write_bytes(target.robot)
    scene = inputs / target.scene_name
    scene.write_bytes(target.scene)
    topology = None
    if target.topology is not None:
        topology = inputs / "topology.yaml"
        topology.write_bytes(target.topology)
    layout = find_layout()
    if layout.in_source_tree and not layout.model_tool.is_file():
        _home.build_target("rbdc-model")
    compilation = compile_robot(robot, scene, topology, target.base, None, layout, mimic=target.mimic)
    module_sources = render_python_module(compilation, layout, module_name, target.float32)
    for generated in render(compilation, layout) + module_sources:
        path = work / "src" / generated.path
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(generated.text)
    return [work / "src" / generated.path for generated in module_sources]


def _run_all(commands: list[list[str]], jobs: int) -> None:
    """Runs the compiler commands, `jobs` at a time, a slot refilled as soon as any command ends (the
    commands come longest first: render_python_module's order); raises with the first failure's
    messages, after cancelling those not yet started."""
    def run(command):
        return command, subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        for future in concurrent.futures.as_completed([pool.submit(run, c) for c in commands]):
            command, process = future.result()
            if process.returncode != 0:
                pool.shutdown(cancel_futures=True)
                raise RuntimeError(f"rbdc.compile: the compiler failed:\n{shlex.join(command)}\n{process.stdout[-4000:]}")


def _build(target: Target, key: str, entry: Path) -> None:
    entry.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=f".{key}-", dir=entry.parent))
    try:
        module_name = f"rbdc_compiled_{key}"
        sources = _generate(target, work, module_name)
        includes = [f"-I{d}" for d in [work / "src", *_include_dirs()]]
        objects = [source.with_suffix(".o") for source in sources]
        compiles = [[*_compiler(), *_flags(), *includes, "-c", str(s), "-o", str(o)] for s, o in zip(sources, objects)]
        link = [*_compiler(), *_flags(), "-shared", *map(str, objects), "-o",
                str(work / (module_name + sysconfig.get_config_var("EXT_SUFFIX")))]
        (work / "commands.txt").write_text("".join(shlex.join(c) + "\n" for c in compiles + [link]))
        _run_all(compiles, int(os.environ.get("RBDC_COMPILE_JOBS", 0)) or os.cpu_count() or 1)
        _run_all([link], 1)
        for o in objects:  # the module is linked; the sources stay for reading
            o.unlink()
        os.rename(work, entry)  # atomic: readers see no entry or a whole one
    finally:
        shutil.rmtree(work, ignore_errors=True)


def compile_target(target: Target):
    """The module of `target`, from the cache or built into it."""
    key = cache_key(target)
    entry = _home.cache_dir() / key
    if _module_file(entry) is None:
        entry.parent.mkdir(parents=True, exist_ok=True)
        with open(entry.parent / f"{key}.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)  # one builder; the others wait, then hit
            if _module_file(entry) is None:
                _build(target, key, entry)
    module = _load(entry)
    module.target = target
    return module


def compile(path_or_model, scene="full", topology=None, base=None, mimic="couple", float32=False):
    """The generated code of a robot and scene as a module with one numpy function per generated
    function (names and layouts of docs/generated_api.md). `path_or_model`: a URDF (or standalone
    topology) path, or an rbdc.Model (its file and loading options are used). `scene`: a bundled
    scene's name or a scene file. `float32`: also compile the float32 instantiation, so that an
    all-float32 batch computes in float32 (twice the SIMD lanes; a third more compile time); without
    it float32 inputs are computed in float64, as the runtime does. The first call for given inputs generates and compiles (tens of
    seconds); later ones, in any process of this user, load the cached module."""
    if hasattr(path_or_model, "source"):  # an rbdc.Model
        source = path_or_model.source
        if source["root"] or source["lock"]:
            raise ValueError("rbdc.compile: a model loaded with root= or lock= cannot be compiled; "
                             "give the URDF and a scene with locked_joints instead")
        path_or_model, topology = source["path"], topology or source["topology"]
        base, mimic = base or source["base"], source["mimic"]
    return compile_target(Target.from_files(path_or_model, scene, topology, base, mimic, float32))
