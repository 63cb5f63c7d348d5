"""docs/ir.schema.json against both sides of the IR: what rbdc-model writes for every bundled robot
is valid, every valid fixture loads in rbdcgen.frontend.ir, and what the schema refuses (a required key
missing, a value of the wrong type) the reader refuses too."""

import copy
import glob
import json
import os
import subprocess
import unittest

import mini_cheetah
from json_schema import SchemaError, errors
from numeric_check import DATA
from rbdcgen.frontend.ir import IRError, load_ir

SCHEMA_PATH = os.path.join(mini_cheetah.ROOT, "docs", "ir.schema.json")
with open(SCHEMA_PATH, encoding="utf-8") as handle:
    SCHEMA = json.load(handle)
FIXTURES = sorted(glob.glob(os.path.join(DATA, "*.json")))
# The bundled robots and the base regenerate gives them (tools/regenerate).
BUNDLED = {"mini_cheetah": "floating", "arm7": "fixed", "humanoid32": "floating"}


def load_json(path):
    with open(path, encoding="utf-8") as handle:
        return json.load(handle)


def wrong_value(schema):
    """A value of a type the property's schema does not allow."""
    if "$ref" in schema:
        schema = SCHEMA["$defs"][schema["$ref"].split("/")[-1]]
    types = schema.get("type", [])
    return "not a number" if "string" not in types else 7


class Schema(unittest.TestCase):
    def test_the_schema_uses_only_what_the_validator_checks(self):
        self.assertEqual(errors(load_json(FIXTURES[0]), SCHEMA), [])
        with self.assertRaises(SchemaError):
            errors({}, {"type": "object", "patternProperties": {}})

    def test_the_validator_reports_the_element(self):
        data = load_json(FIXTURES[0])
        data["joints"][2]["type"] = "helical"
        del data["feet"][0]["offset"]
        data["extra"] = 1
        found = errors(data, SCHEMA)
        self.assertEqual(len(found), 3, found)
        self.assertIn("$.joints[2].type", found[0] + found[1] + found[2])


class Reader(unittest.TestCase):
    def test_every_fixture_is_valid_and_loads(self):
        self.assertGreaterEqual(len(FIXTURES), 2)
        for path in FIXTURES:
            self.assertEqual(errors(load_json(path), SCHEMA), [], path)
            self.assertEqual(load_ir(path).nb, load_json(path)["nb"])

    def test_what_the_schema_refuses_the_reader_refuses(self):
        data = load_json(os.path.join(DATA, "tiny_floating.json"))
        data["couplings"] = [{"follower": 2, "leader": 1, "multiplier": 0.5, "offset": 0.0}]
        self.assertEqual(errors(data, SCHEMA), [])
        load_ir(data)
        # (container inside the document, its schema) for the top level and one of each element.
        places = [(lambda d: d, SCHEMA)] + [
            (lambda d, key=key: d[key][0], SCHEMA["$defs"][element])
            for key, element in (("bodies", "body"), ("joints", "joint"), ("feet", "foot"),
                                 ("couplings", "coupling"))]
        for container, schema in places:
            for key in schema["required"]:
                for change in ("remove", "retype"):
                    broken = copy.deepcopy(data)
                    if change == "remove":
                        del container(broken)[key]
                    else:
                        container(broken)[key] = wrong_value(schema["properties"][key])
                    self.assertNotEqual(errors(broken, SCHEMA), [], (key, change))
                    with self.assertRaises(IRError, msg="%s %s" % (change, key)):
                        load_ir(broken)


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class Writer(unittest.TestCase):
    def test_rbdc_model_output_for_every_bundled_robot_is_valid(self):
        for robot, base in BUNDLED.items():
            urdf = os.path.join(mini_cheetah.ROOT, "robots", robot + ".urdf")
            result = subprocess.run([mini_cheetah.model_tool(), urdf, "--%s-base" % base],
                                    capture_output=True, text=True)
            self.assertEqual(result.returncode, 0, result.stderr)
            data = json.loads(result.stdout)
            self.assertEqual(errors(data, SCHEMA), [], robot)
            self.assertEqual(load_ir(data).name, robot)

    def test_actuators_are_valid_and_read(self):
        """The Mini Cheetah with rotors (robots/mini_cheetah_rotors.topology.yaml) and an armature."""
        urdf = os.path.join(mini_cheetah.ROOT, "robots", "mini_cheetah.urdf")
        topology = os.path.join(mini_cheetah.ROOT, "robots", "mini_cheetah_rotors.topology.yaml")
        result = subprocess.run([mini_cheetah.model_tool(), urdf, "--topology", topology,
                                 "--armature", "LF_abad_joint=0.001"], capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        data = json.loads(result.stdout)
        self.assertEqual(errors(data, SCHEMA), [])
        robot = load_ir(data)
        abad = robot.joints[1].actuator
        self.assertEqual((abad.armature, abad.rotor.gear_ratio, abad.rotor.mass), (0.001, 6, 0.055))
        self.assertAlmostEqual(sum(j.actuator.rotor.mass for j in robot.joints[1:]), 0.66, places=12)
        data["joints"][1]["actuator"]["armature"] = -1.0
        self.assertNotEqual(errors(data, SCHEMA), [])
        with self.assertRaises(IRError):
            load_ir(data)


if __name__ == "__main__":
    unittest.main()
