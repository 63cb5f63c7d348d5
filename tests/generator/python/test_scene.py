"""Scene files: validation with clear errors, the bundled scenes, and what a scene removes
(zero inputs vanish from signatures and graphs, fewer operations)."""

import os
import tempfile
import unittest

from mini_cheetah import SCENES
from numeric_check import DATA, evaluate, max_relative_error, random_state
from rbdcgen.graph.flops import count_ops
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import QUANTITIES, SceneError, default_scene, load_scene, scene_from_dict
from rbdcgen.passes.trace import trace_function
from rbdcgen.passes.schedule import trace_scene

ROBOT = load_ir(os.path.join(DATA, "tiny_floating.json"))
FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))


class Validation(unittest.TestCase):
    def assert_refused(self, data, *words):
        with self.assertRaises(SceneError) as caught:
            scene_from_dict(data, source="s.yaml")
        for word in ("s.yaml",) + words:
            self.assertIn(word, str(caught.exception))

    def test_bad_scenes_are_refused_with_the_problem_named(self):
        self.assert_refused({"name": "x", "colour": 1}, "colour", "unknown key")
        self.assert_refused({"name": "x", "quantities": ["mass_matrx"]}, "mass_matrx")
        self.assert_refused({"name": "x", "zero_inputs": ["q"]}, "zero_inputs", "'q'")
        self.assert_refused({"name": "x", "gravity": [0, 1]}, "gravity")
        self.assert_refused({"name": "x", "base": "hovering"}, "base")
        self.assert_refused({"quantities": []}, "name")
        self.assert_refused({"name": "x", "locked_joints": {"knee": "up"}}, "locked_joints")

    def test_unknown_foot_is_refused_when_resolved(self):
        scene = scene_from_dict({"name": "x", "feet": ["lower_foot", "hand"]}, source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.feet_for(ROBOT)
        self.assertIn("hand", str(caught.exception))
        scene = scene_from_dict({"name": "x", "feet": ["lower_foot"],
                                 "contacts": ["slider_foot"]}, source="s.yaml")
        with self.assertRaises(SceneError):
            scene.contacts_for(ROBOT)

    def test_missing_file_and_bad_yaml(self):
        with self.assertRaises(SceneError) as caught:
            load_scene("/nonexistent/scene.yaml")
        self.assertIn("/nonexistent/scene.yaml", str(caught.exception))
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as handle:
            handle.write("name: [unclosed\n")
        try:
            with self.assertRaises(SceneError):
                load_scene(handle.name)
        finally:
            os.unlink(handle.name)

    def test_gravity_none_and_defaults(self):
        self.assertEqual(scene_from_dict({"name": "x", "gravity": "none"}).gravity_for(ROBOT),
                         (0.0, 0.0, 0.0))
        self.assertEqual(default_scene().gravity_for(ROBOT), ROBOT.gravity)
        self.assertEqual(default_scene().quantities_for(ROBOT), QUANTITIES)
        self.assertNotIn("osc_open_chain", default_scene().quantities_for(FIXED))
        with self.assertRaises(SceneError):
            scene_from_dict({"name": "x", "quantities": ["osc_closed_chain"]}).quantities_for(FIXED)

    def test_bundled_scenes_load(self):
        for name in ("full", "gravity_compensation", "stance_osc", "kinematics_only"):
            scene = load_scene(os.path.join(SCENES, name + ".yaml"))
            self.assertEqual(scene.name, name)
            self.assertTrue(scene.quantities_for(ROBOT))


class WhatASceneRemoves(unittest.TestCase):
    def test_gravity_compensation_has_no_velocity_and_fewer_operations(self):
        scene = load_scene(os.path.join(SCENES, "gravity_compensation.yaml"))
        compensation = trace_function(ROBOT, scene, "inverse_dynamics")
        full = trace_function(ROBOT, default_scene(), "inverse_dynamics")
        self.assertEqual([a.name for a in compensation.inputs], ["q", "a"])
        self.assertEqual([a.name for a in full.inputs], ["q", "v", "a"])
        self.assertFalse(any(n.op == "sym" and n.value[0] == "v"
                             for n in compensation.graph.nodes))
        self.assertLess(count_ops(compensation)["total"], count_ops(full)["total"])
        # The full function's values at v = 0, up to round-off: each sum adds its terms in their
        # order of arrival (graph/reassociate.py), which changes once v's terms are gone.
        state = random_state(ROBOT, 2, 7)
        state["v"] = [0.0] * ROBOT.nv
        self.assertLess(max_relative_error(evaluate(compensation, state)["tau"], evaluate(full, state)["tau"]), 1e-14)

    def test_zero_foot_forces_remove_the_argument(self):
        scene = scene_from_dict({"name": "x", "zero_inputs": ["f"]})
        fd = trace_function(ROBOT, scene, "forward_dynamics")
        self.assertEqual([a.name for a in fd.inputs], ["q", "v", "tau"])

    def test_feet_selection_shrinks_outputs(self):
        scene = scene_from_dict({"name": "x", "feet": ["slider_foot"]})
        jac = trace_function(ROBOT, scene, "feet_jacobian")
        self.assertEqual((jac.outputs[0].rows, jac.outputs[0].cols), (3, ROBOT.nv))

    def test_no_gravity_scene_has_zero_gravity_terms(self):
        scene = scene_from_dict({"name": "x", "gravity": "none", "quantities": ["gravity_terms"]})
        (fn,) = trace_scene(ROBOT, scene)
        self.assertTrue(all(e.is_const(0.0) for e in fn.values["g"]))
        self.assertEqual(count_ops(fn)["total"], 0)


if __name__ == "__main__":
    unittest.main()
