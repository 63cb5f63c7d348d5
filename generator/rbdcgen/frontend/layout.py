"""Where rbdc's parts live: the source tree (with a CMake build dir) or an install prefix.

The launcher sets RBDC_HOME to its own directory. In the source tree that is the repository root and
the C++ tools come from RBDC_BUILD_DIR (default <root>/build); after `cmake --install` it is
<prefix>/bin and everything else sits under <prefix>/share/rbdc, <prefix>/include and <prefix>/lib.
Single paths can be overridden with RBDC_MODEL_TOOL, RBDC_EVAL_TOOL, RBDC_RUNTIME_LIBRARY and
RBDC_RUNTIME_INCLUDE (the tests use these to point at their own build dir).
"""
import os
from dataclasses import dataclass
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent.parent  # generator/rbdcgen


@dataclass(frozen=True)
class Layout:
    root: Path               # repository root or <prefix>/share/rbdc
    templates: Path
    scenes: Path
    model_tool: Path
    eval_tool: Path
    runtime_include: Path
    runtime_library: Path
    verify_flags: Path       # rbdc-verify.json: compiler and external libraries (cmake/RbdcVerifyFlags.cmake)
    in_source_tree: bool


def _source_tree_root():
    candidate = PACKAGE_DIR.parent.parent
    return candidate if (candidate / "templates").is_dir() and (candidate / "runtime").is_dir() else None


def find_layout() -> Layout:
    env = os.environ
    root = _source_tree_root()
    if root is not None:
        build = Path(env.get("RBDC_BUILD_DIR", root / "build"))
        layout = Layout(root=root, templates=root / "templates", scenes=root / "scenes",
                        model_tool=build / "bin" / "rbdc-model", eval_tool=build / "bin" / "rbdc-eval",
                        runtime_include=root / "runtime" / "include",
                        runtime_library=build / "runtime" / "librbdc_runtime.a",
                        verify_flags=build / "rbdc-verify.json", in_source_tree=True)
    else:
        # Installed: the package sits in <prefix>/share/rbdc/generator/rbdcgen.
        share = PACKAGE_DIR.parent.parent
        prefix = share.parent.parent
        layout = Layout(root=share, templates=share / "templates", scenes=share / "scenes",
                        model_tool=prefix / "bin" / "rbdc-model", eval_tool=prefix / "bin" / "rbdc-eval",
                        runtime_include=prefix / "include",
                        runtime_library=_installed_library(prefix),
                        verify_flags=share / "rbdc-verify.json", in_source_tree=False)
    overrides = {"model_tool": "RBDC_MODEL_TOOL", "eval_tool": "RBDC_EVAL_TOOL",
                 "runtime_library": "RBDC_RUNTIME_LIBRARY", "runtime_include": "RBDC_RUNTIME_INCLUDE"}
    changes = {field: Path(env[var]) for field, var in overrides.items() if env.get(var)}
    return Layout(**{**layout.__dict__, **changes})


def _installed_library(prefix: Path) -> Path:
    for libdir in ("lib", "lib64"):
        candidate = prefix / libdir / "librbdc_runtime.a"
        if candidate.exists():
            return candidate
    return prefix / "lib" / "librbdc_runtime.a"


def display_path(path: Path, layout: Layout) -> str:
    """The path as written into banners: relative to the repository when inside it, else as given."""
    resolved = Path(path).resolve()
    try:
        return resolved.relative_to(layout.root).as_posix()
    except ValueError:
        return Path(path).as_posix()
