"""Where the parts rbdc's Python package needs live: the source tree (generator/, templates/, a CMake
build dir) or an install prefix (<prefix>/share/rbdc). Mirrors the `rbdc` launcher and
generator/rbdcgen/layout.py; RBDC_BUILD_DIR chooses the build dir as it does for the launcher."""
import os
import subprocess
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
NATIVE_INCLUDE = PACKAGE_DIR / "native"  # rbdc_py/batch_call.hpp


def source_root():
    """The repository root when the package is imported from python/rbdc of a source tree."""
    root = PACKAGE_DIR.parent.parent
    return root if (root / "generator" / "rbdcgen").is_dir() and (root / "runtime").is_dir() else None


def share_dir() -> Path:
    """<prefix>/share/rbdc of an install (the package sits in <prefix>/lib/python3/dist-packages/rbdc)."""
    return Path(os.environ.get("RBDC_SHARE_DIR", PACKAGE_DIR.parents[3] / "share" / "rbdc"))


def generator_dir() -> Path:
    root = source_root()
    return root / "generator" if root else share_dir() / "generator"


def build_dir() -> Path:
    root = source_root()
    return Path(os.environ.get("RBDC_BUILD_DIR", root / "build" if root else "."))


def build_target(target: str) -> None:
    """Builds one CMake target of the source tree in build_dir(), configuring it first if needed
    (what the `rbdc` launcher does on first use)."""
    root, build = source_root(), build_dir()
    if root is None:
        raise RuntimeError(f"rbdc: {target} is missing from the install; reinstall rbdc")
    log = build / f"rbdc-build-{target}.log"
    build.mkdir(parents=True, exist_ok=True)
    steps = [["cmake", "--build", str(build), "--target", target, "-j", "2"]]
    if not (build / "CMakeCache.txt").is_file():
        steps.insert(0, ["cmake", "-S", str(root), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"])
    with open(log, "w") as out:
        for step in steps:
            if subprocess.run(step, stdout=out, stderr=subprocess.STDOUT).returncode != 0:
                raise RuntimeError(f"rbdc: building {target} in {build} failed; see {log}")


def cache_dir() -> Path:
    """Per-user cache of compiled modules: RBDC_CACHE_DIR, else $XDG_CACHE_HOME/rbdc, else ~/.cache/rbdc."""
    if os.environ.get("RBDC_CACHE_DIR"):
        return Path(os.environ["RBDC_CACHE_DIR"])
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "rbdc"
