"""The real Mini Cheetah IR for the tests: robots/mini_cheetah.urdf through rbdc-model.

The tool is found through $RBDC_MODEL, else build/bin/rbdc-model; tests skip with a clear message
only when the tool is not built (the CI builds it first)."""

import json
import os
import subprocess

from numeric_check import HERE
from rbdcgen.frontend.ir import load_ir

ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
URDF = os.path.join(ROOT, "robots", "mini_cheetah.urdf")
HUMANOID32 = os.path.join(ROOT, "robots", "humanoid32.urdf")
SCENES = os.path.join(ROOT, "scenes")


def model_tool():
    return os.environ.get("RBDC_MODEL") or os.path.join(ROOT, "build", "bin", "rbdc-model")


def skip_reason():
    if not os.path.isfile(model_tool()):
        return "rbdc-model is not built (%s); build the rbdc-model target or set RBDC_MODEL" % (
            model_tool())
    if not os.path.isfile(URDF):
        return "%s does not exist" % URDF
    return None


_cache = {}


def load(base="floating", urdf=URDF):
    """A robot file (the Mini Cheetah unless `urdf`: another bundled robot) through rbdc-model."""
    if (urdf, base) not in _cache:
        result = subprocess.run([model_tool(), urdf, "--%s-base" % base], capture_output=True,
                                text=True, check=True)
        _cache[urdf, base] = load_ir(json.loads(result.stdout))
    return _cache[urdf, base]
