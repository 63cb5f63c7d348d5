"""IR loading: the fixture loads into plain frozen data; malformed IR is refused with the file,
element and problem named."""

import copy
import dataclasses
import json
import os
import unittest

from numeric_check import DATA
from rbdcgen.frontend.ir import IRError, load_ir

PATH = os.path.join(DATA, "tiny_floating.json")
with open(PATH, encoding="utf-8") as handle:
    RAW = json.load(handle)


class Loading(unittest.TestCase):
    def test_fixture(self):
        robot = load_ir(PATH)
        self.assertEqual((robot.nb, robot.nq, robot.nv, robot.n_joints), (4, 10, 9, 3))
        self.assertEqual(robot.parent, (-1, 0, 1, 0))
        self.assertEqual(robot.joints[3].type, "prismatic")
        self.assertEqual(robot.foot("slider_foot").body, 3)
        with self.assertRaises(dataclasses.FrozenInstanceError):
            robot.nb = 5

    def assert_refused(self, mutate, *words):
        data = copy.deepcopy(RAW)
        mutate(data)
        with self.assertRaises(IRError) as caught:
            load_ir(data)
        for word in words:
            self.assertIn(word, str(caught.exception))

    def test_malformed_ir_is_refused_with_the_element_named(self):
        self.assert_refused(lambda d: d.update(format="rbdc-ir-0"), "format")
        self.assert_refused(lambda d: d.pop("bodies"), "bodies")
        self.assert_refused(lambda d: d["bodies"][1].update(mass="heavy"), "bodies[1].mass")
        self.assert_refused(lambda d: d["joints"][2].update(type="helical"), "joints[2].type")
        self.assert_refused(lambda d: d["joints"][2].update(parent=3), "joints[2].parent")
        self.assert_refused(lambda d: d["joints"][1].update(axis=[1, 0]), "joints[1].axis")
        self.assert_refused(lambda d: d["feet"][0].update(body=9), "feet[0].body")
        self.assert_refused(lambda d: d.update(nv=4), "nq/nv")
        self.assert_refused(lambda d: d["kappa"].__setitem__(1, 5), "kappa[1]")

    def test_unreadable_file(self):
        with self.assertRaises(IRError) as caught:
            load_ir("/nonexistent/robot.json")
        self.assertIn("/nonexistent/robot.json", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
