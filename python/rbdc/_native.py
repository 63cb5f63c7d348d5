"""The runtime's extension module rbdc._runtime: beside this file in an install, else in the build
dir of the source tree (built on first use, as the `rbdc` launcher builds its tools)."""
import importlib.machinery
import importlib.util
import sysconfig

from . import _home

TARGET = "rbdc_python"  # CMake target of rbdc/_runtime (python/CMakeLists.txt)


def _load_from(path):
    loader = importlib.machinery.ExtensionFileLoader("rbdc._runtime", str(path))
    spec = importlib.util.spec_from_file_location("rbdc._runtime", path, loader=loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def load_runtime():
    try:
        from . import _runtime  # installed next to this file
        return _runtime
    except ImportError:
        pass
    built = _home.build_dir() / "python" / "rbdc" / ("_runtime" + sysconfig.get_config_var("EXT_SUFFIX"))
    if not built.is_file():
        _home.build_target(TARGET)
    return _load_from(built)
