"""Traced signatures follow docs/generated_api.md; degenerate robots trace or fail clearly."""

import copy
import json
import os
import unittest

from numeric_check import DATA, evaluate, max_relative_error, random_state
from rbdcgen.backend.emit import emit_body
from rbdcgen.graph.flops import count_ops
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene
from rbdcgen.passes.trace import TraceError, trace_function
from rbdcgen.passes.schedule import trace_scene

with open(os.path.join(DATA, "tiny_floating.json"), encoding="utf-8") as handle:
    RAW = json.load(handle)

SIGNATURES = {
    "feet_positions": (["q"], [("p", 3, 2)]),
    "feet_velocities": (["q", "v"], [("pdot", 3, 2)]),
    "feet_jacobian": (["q"], [("J", 6, 9)]),
    "quadratic_velocity_terms": (["q", "v"], [("c", 9, 1)]),
    "gravity_terms": (["q"], [("g", 9, 1)]),
    "bias": (["q", "v"], [("cg", 9, 1)]),
    "feet_force_terms": (["q", "f"], [("tau_e", 9, 1)]),
    "inverse_dynamics": (["q", "v", "a"], [("tau", 9, 1)]),
    "mass_matrix": (["q"], [("M", 9, 9)]),
    "mass_matrix_factor": (["q"], [("L", 9, 9), ("D", 9, 1), ("D_inv", 9, 1)]),
    "forward_dynamics": (["q", "v", "tau", "f"], [("a", 9, 1)]),
    "osc_open_chain": (["q", "v", "f"], [("Lambda", 6, 6), ("JbarT", 6, 3), ("b", 6, 1)]),
    "osc_closed_chain": (["q", "v", "ground_mass"],
                         [("Lambda", 6, 6), ("JbarT", 6, 3), ("b", 6, 1)]),
}


class Signatures(unittest.TestCase):
    def test_every_function_has_the_documented_signature(self):
        functions = trace_scene(load_ir(RAW), default_scene())
        self.assertEqual([fn.name for fn in functions], list(SIGNATURES))
        for fn in functions:
            inputs, outputs = SIGNATURES[fn.name]
            self.assertEqual([a.name for a in fn.inputs], inputs, fn.name)
            self.assertEqual([(a.name, a.rows, a.cols) for a in fn.outputs], outputs, fn.name)
            self.assertTrue(fn.doc)


class DegenerateRobots(unittest.TestCase):
    def test_a_single_welded_body_has_empty_joint_space_functions(self):
        data = copy.deepcopy(RAW)
        data.update(nb=1, nq=0, nv=0, floating_base=False, PRED=[], SUCC=[], kappa=[[]], mu=[[]],
                    nu=[[0]], bodies=data["bodies"][:1], joints=data["joints"][:1],
                    feet=[{"name": "f", "body": 0, "offset": [0, 0, -0.1]}])
        data["lambda"] = []
        data["joints"][0]["type"] = "fixed"
        robot = load_ir(data)
        for fn in trace_scene(robot, default_scene()):
            statements = [l for l in emit_body(fn) if not l.startswith("//")]
            self.assertEqual(len(statements), sum(a.size for a in fn.outputs), fn.name)
        self.assertEqual(emit_body(trace_function(robot, default_scene(), "feet_positions"))[-1],
                         "p[2] = Scalar(-0.1);")

    def test_a_massless_moving_body_is_a_clear_error_where_a_pivot_vanishes(self):
        data = copy.deepcopy(RAW)
        data["bodies"][2].update(mass=0.0, inertia_com=[[0, 0, 0], [0, 0, 0], [0, 0, 0]])
        robot = load_ir(data)
        trace_function(robot, default_scene(), "mass_matrix")
        with self.assertRaises(TraceError) as caught:
            trace_function(robot, default_scene(), "forward_dynamics")
        self.assertIn("forward_dynamics", str(caught.exception))
        self.assertIn("massless", str(caught.exception))


class KnownInputs(unittest.TestCase):
    def test_a_function_traced_with_known_inputs_folds_to_its_value_there(self):
        robot = load_ir(RAW)
        state = random_state(robot, 2, seed=3)
        symbolic = evaluate(trace_function(robot, default_scene(), "mass_matrix"), state)["M"]
        folded = trace_function(robot, default_scene(), "mass_matrix", known_inputs={"q": state["q"]})
        self.assertTrue(all(x.op == "const" for x in folded.values["M"]))
        self.assertLess(max_relative_error([x.value for x in folded.values["M"]], symbolic), 1e-14)


class CombinedFunctions(unittest.TestCase):
    def test_step_terms_equal_the_separate_functions_in_fewer_operations(self):
        robot = load_ir(RAW)
        scene = default_scene()
        combined = trace_function(robot, scene, "step_terms")
        parts = {name: trace_function(robot, scene, name) for name in
                 ("feet_positions", "feet_velocities", "feet_jacobian", "mass_matrix_factor",
                  "forward_dynamics")}
        state = random_state(robot, len(robot.feet), 5)
        state["f"] = [0.0] * len(state["f"])  # a₀: no foot forces
        got = evaluate(combined, state)
        for name, outputs in (("feet_positions", {"p": "p"}), ("feet_velocities", {"pdot": "pdot"}),
                              ("feet_jacobian", {"J": "J"}), ("forward_dynamics", {"a": "a"}),
                              ("mass_matrix_factor", {"L": "L", "D": "D", "D_inv": "D_inv"})):
            want = evaluate(parts[name], state)
            for ours, theirs in outputs.items():
                self.assertLess(max_relative_error(got[ours], want[theirs]), 1e-13, ours)
        nv, v = robot.nv, state["v"]
        omega = [sum(got["Jw"][c * 3 * len(robot.feet) + r] * v[c] for c in range(nv))
                 for r in range(3 * len(robot.feet))]
        self.assertLess(max_relative_error(got["omega"], omega), 1e-13)
        self.assertLess(count_ops(combined)["total"],
                        sum(count_ops(fn)["total"] for fn in parts.values()))


if __name__ == "__main__":
    unittest.main()
