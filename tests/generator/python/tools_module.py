"""A script of tools/ loaded as a module, for its tests. tools/ is not a package: its scripts import
one another from their own folder, so the folder goes on sys.path first."""
import importlib.util
import os
import sys

from mini_cheetah import ROOT

TOOLS = os.path.join(ROOT, "tools")


def load(name):
    """tools/<name>.py as a module (its main() not run)."""
    if TOOLS not in sys.path:
        sys.path.insert(0, TOOLS)
    spec = importlib.util.spec_from_file_location(name, os.path.join(TOOLS, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
