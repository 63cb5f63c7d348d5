"""Properties of the generator's readers (docs/fuzzing.md): every input to load_ir and load_scene,
from raw bytes to valid files with one part replaced by arbitrary JSON, ends in a result or in the
reader's own error (IRError, SceneError: the types the command line reports) whose message names the
file; never another exception. What loads holds finite numbers only.

Few examples in CI; the long run: RBDC_HYPOTHESIS_PROFILE=long (10^4 examples per property).
"""

import copy
import dataclasses
import json
import math
import os
import tempfile
import unittest

import yaml
from hypothesis import HealthCheck, given, settings, strategies as st

from numeric_check import DATA
from rbdcgen.frontend.ir import IRError, load_ir
from rbdcgen.frontend.scene import KEYS, SceneError, load_scene, scene_from_dict

# No example database: nothing is written into the source tree.
settings.register_profile("ci", max_examples=40, deadline=None, derandomize=True, database=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("long", max_examples=10_000, deadline=None, database=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("RBDC_HYPOTHESIS_PROFILE", "ci"))

with open(os.path.join(DATA, "tiny_floating.json"), encoding="utf-8") as _handle:
    VALID_IR = json.load(_handle)
# Every scene key (scene.KEYS), so that each can be replaced or deleted.
VALID_SCENE = {"name": "stance", "quantities": ["mass_matrix", "feet_jacobian", "frame_jacobians"],
               "gravity": [0, 0, -9.81], "base": "fixed", "locked_joints": {"hinge": 0.5},
               "feet": ["slider_foot"], "frames": ["tool"], "contacts": ["slider_foot"], "zero_inputs": ["v"],
               "derivatives": ["gravity_derivatives"], "actuators": "full", "schedule": "auto",
               "frame_axes": "world"}

# Any JSON value: the numbers include huge, tiny, NaN and ±Infinity (Python's json writes and reads them).
JSON = st.recursive(
    st.none() | st.booleans() | st.integers(min_value=-2**70, max_value=2**70) | st.floats()
    | st.text(max_size=12),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
    max_leaves=12)


def paths(value, prefix=()):
    """Every path (keys and indices) into a JSON value, the root included."""
    yield prefix
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, child in items:
        yield from paths(child, prefix + (key,))


@st.composite
def mutated(draw, valid):
    """`valid` with one part replaced by an arbitrary JSON value, or deleted."""
    data = copy.deepcopy(valid)
    path = draw(st.sampled_from(list(paths(data))))
    if not path:
        return draw(JSON)
    parent = data
    for key in path[:-1]:
        parent = parent[key]
    if draw(st.booleans()):
        del parent[path[-1]]
    else:
        parent[path[-1]] = draw(JSON)
    return data


def numbers(value):
    """Every float inside a reader's result (dataclasses, tuples)."""
    if isinstance(value, float):
        yield value
    elif dataclasses.is_dataclass(value):
        for field in dataclasses.fields(value):
            yield from numbers(getattr(value, field.name))
    elif isinstance(value, (tuple, list)):
        for item in value:
            yield from numbers(item)


class ReaderProperties(unittest.TestCase):
    def setUp(self):
        handle, self.path = tempfile.mkstemp(prefix="rbdc-reader-")
        os.close(handle)
        self.addCleanup(os.remove, self.path)

    def assert_result_or_error(self, load, error, content):
        with open(self.path, "wb") as handle:
            handle.write(content)
        try:
            result = load(self.path)
        except error as caught:
            self.assertIn(self.path, str(caught))
            return
        self.assertTrue(all(math.isfinite(x) for x in numbers(result)), result)

    @given(st.binary(max_size=300))
    def test_ir_from_any_bytes(self, content):
        self.assert_result_or_error(load_ir, IRError, content)

    @given(mutated(VALID_IR))
    def test_ir_with_any_part_replaced(self, data):
        self.assert_result_or_error(load_ir, IRError, json.dumps(data).encode())

    @given(st.binary(max_size=300))
    def test_scene_from_any_bytes(self, content):
        self.assert_result_or_error(load_scene, SceneError, content)

    @given(mutated(VALID_SCENE))
    def test_scene_with_any_part_replaced(self, data):
        self.assert_result_or_error(load_scene, SceneError, yaml.safe_dump(data, allow_unicode=True).encode())

    def test_valid_scene_holds_every_key(self):  # a key added to the reader is mutated too
        self.assertEqual(set(VALID_SCENE), set(KEYS))
        self.assertEqual(scene_from_dict(VALID_SCENE).frames, ("tool",))

    def test_deep_nesting_and_bad_encodings(self):  # what random bytes rarely reach
        for content in (b"[" * 100_000, b"\xff\xfe{}", b'{"format": "\xc3("}', b"a: [" * 50_000,
                        b"1" * 5000):
            self.assert_result_or_error(load_ir, IRError, content)
            self.assert_result_or_error(load_scene, SceneError, content)


if __name__ == "__main__":
    unittest.main()
