"""Frames and centroidal functions (issue 21) in the generator alone: the scene's frames resolve with
clear errors, the IR's frames are read and checked, the traced functions agree with each other
(J v = the frame velocities, A_G's linear rows = m J_c, M · M⁻¹ = 1) on a fixture with a rotated,
offset frame, and the scene's frame_axes keeps one output of each frame function, unchanged. The comparison with the runtime is rbdc verify's (tests/generator/CMakeLists.txt)."""

import copy
import dataclasses
import json
import os
import unittest

from numeric_check import DATA, evaluate, random_state
from rbdcgen.frontend.ir import Frame, IRError, load_ir
from rbdcgen.frontend.scene import SceneError, WHOLE_BODY, scene_from_dict
from rbdcgen.passes.trace import FRAME_AXES_OUTPUT, trace_function

RAW = json.load(open(os.path.join(DATA, "tiny_floating.json")))
ROTATED = ((0.0, -1.0, 0.0), (0.6, 0.0, 0.8), (-0.8, 0.0, 0.6))  # body → frame coordinates
ROBOT = dataclasses.replace(load_ir(RAW), frames=(
    Frame("base_frame", 0, ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)), (0.0, 0.0, 0.0)),
    Frame("tool", 3, ROTATED, (0.05, -0.02, 0.1))))
SCENE = scene_from_dict({"name": "x", "quantities": list(WHOLE_BODY), "frames": ["tool", "base_frame"]})


def matvec(rows, cols, column_major, x):
    return [sum(column_major[c * rows + r] * x[c] for c in range(cols)) for r in range(rows)]


class Resolution(unittest.TestCase):
    def test_unknown_frame_is_refused_naming_it(self):
        scene = scene_from_dict({"name": "x", "frames": ["tool", "gripper"]}, source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.frames_for(ROBOT)
        self.assertIn("s.yaml: frames: unknown frame 'gripper'", str(caught.exception))

    def test_frame_functions_need_frames(self):
        scene = scene_from_dict({"name": "x", "quantities": ["frame_jacobians"]}, source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.quantities_for(ROBOT)
        self.assertIn("the scene lists no frames", str(caught.exception))

    def test_ir_frames_are_read_and_checked(self):
        data = copy.deepcopy(RAW)
        data["frames"] = [{"name": "tool", "body": 3, "rotation": [list(r) for r in ROTATED],
                           "translation": [0.05, -0.02, 0.1]}]
        self.assertEqual(load_ir(data).frames[0].rotation, ROTATED)
        data["frames"][0]["body"] = 9
        with self.assertRaises(IRError) as caught:
            load_ir(data)
        self.assertIn("frames[0].body", str(caught.exception))


class FrameAxes(unittest.TestCase):
    def test_one_axes_choice_keeps_that_output_alone_and_unchanged(self):
        state = random_state(ROBOT, len(ROBOT.feet), 4)
        for name, outputs in FRAME_AXES_OUTPUT.items():
            both = evaluate(trace_function(ROBOT, SCENE, name), state)
            self.assertEqual(set(both), set(outputs.values()))
            for axes, kept in outputs.items():
                scene = dataclasses.replace(SCENE, frame_axes=axes)
                self.assertEqual(evaluate(trace_function(ROBOT, scene, name), state), {kept: both[kept]})

    def test_a_bad_choice_is_refused_naming_the_key(self):
        with self.assertRaises(SceneError) as caught:
            scene_from_dict({"name": "x", "frame_axes": "body"}, source="s.yaml")
        self.assertIn("s.yaml: frame_axes: expected both | world | local, got 'body'", str(caught.exception))


class Identities(unittest.TestCase):
    def setUp(self):
        self.state = random_state(ROBOT, len(ROBOT.feet), 3)
        self.out = {name: evaluate(trace_function(ROBOT, SCENE, name), self.state) for name in WHOLE_BODY}

    def assert_close(self, got, want, tolerance=1e-12):
        for g, w in zip(got, want):
            self.assertAlmostEqual(g, w, delta=tolerance * (1 + abs(w)))

    def test_jacobians_times_v_are_the_frame_velocities(self):
        J, V = self.out["frame_jacobians"], self.out["frame_velocities"]
        nv, v = ROBOT.nv, self.state["v"]
        for jac, vel in (("J_local", "v_local"), ("J_world", "v_world")):
            self.assert_close(matvec(12, nv, J[jac], v), V[vel][0:6] + V[vel][6:12])
        self.assertNotEqual(V["v_local"][0:6], V["v_world"][0:6])  # the rotation did something

    def test_momentum_matrix_linear_rows_are_mass_times_com_jacobian(self):
        nv, mass = ROBOT.nv, sum(b.mass for b in ROBOT.bodies)
        A, J_c = self.out["centroidal_momentum_matrix"]["A_G"], self.out["center_of_mass_jacobian"]["J_c"]
        self.assert_close([A[c * 6 + 3 + r] / mass for c in range(nv) for r in range(3)], J_c)
        v = self.state["v"]
        self.assert_close(matvec(3, nv, J_c, v), self.out["center_of_mass"]["com_velocity"])

    def test_mass_matrix_times_its_inverse_is_the_identity(self):
        nv = ROBOT.nv
        M = evaluate(trace_function(ROBOT, SCENE, "mass_matrix"), self.state)["M"]
        M_inv = self.out["mass_matrix_inverse"]["M_inv"]
        for c in range(nv):
            column = matvec(nv, nv, M, M_inv[c * nv:(c + 1) * nv])
            self.assert_close(column, [1.0 if r == c else 0.0 for r in range(nv)], 1e-10)


if __name__ == "__main__":
    unittest.main()
