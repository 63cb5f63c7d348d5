"""Shared fixtures of the rbdc Python tests (docs/python.md): one cache directory per run, the arm7
test scene compiled once, the Mini Cheetah feet scene compiled by two processes at once."""
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
ARM7 = ROOT / "robots" / "arm7.urdf"
CHEETAH = ROOT / "robots" / "mini_cheetah.urdf"
ARM7_SCENE = HERE / "arm7_small.yaml"
CHEETAH_SCENE = HERE / "cheetah_feet.yaml"

sys.path.insert(0, str(ROOT / "python"))
import rbdc  # noqa: E402


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory):
    path = tmp_path_factory.mktemp("rbdc-cache")
    os.environ["RBDC_CACHE_DIR"] = str(path)
    return path


@pytest.fixture(scope="session")
def arm7_model():
    return rbdc.Model.from_urdf(ARM7, base="fixed")


@pytest.fixture(scope="session")
def cheetah_model():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rbdc.ModelWarning)
        return rbdc.Model.from_urdf(CHEETAH)


@pytest.fixture(scope="session")
def arm7(cache_dir):
    return rbdc.compile(ARM7, scene=ARM7_SCENE, base="fixed", float32=True)


COMPILE_IN_CHILD = """
import sys; sys.path.insert(0, {python!r})
import rbdc
print(rbdc.compile({robot!r}, scene={scene!r}).cache_entry)
"""


@pytest.fixture(scope="session")
def cheetah_feet(cache_dir):
    """Compiled by two processes started together (the cache's lock and atomic rename), then loaded
    here from the cache."""
    code = COMPILE_IN_CHILD.format(python=str(ROOT / "python"), robot=str(CHEETAH), scene=str(CHEETAH_SCENE))
    children = [subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 text=True) for _ in range(2)]
    results = [child.communicate() + (child.returncode,) for child in children]
    for out, err, code_ in results:
        assert code_ == 0, err
    entries = {out.strip().splitlines()[-1] for out, _, _ in results}
    assert len(entries) == 1
    return rbdc.compile(CHEETAH, scene=CHEETAH_SCENE)


def random_states(rng, n, nq, nv, floating):
    q = rng.uniform(-1, 1, (n, nq))
    if floating:
        q[:, 3:7] /= np.linalg.norm(q[:, 3:7], axis=1, keepdims=True)
    return q, rng.uniform(-1, 1, (n, nv)), rng.uniform(-1, 1, (n, nv))
