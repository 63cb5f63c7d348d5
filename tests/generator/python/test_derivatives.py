"""Derivative functions (rbdcgen/derivatives.py): tangents of the traced DAG equal central finite
differences of the traced primal functions on the manifold (q ⊕ δ), on the tiny robots, floating
and fixed base; the manifold seeding equals the derivative of the step q ⊕ δ; scenes select them."""

import os
import unittest

import mini_cheetah
from mini_cheetah import SCENES
from numeric_check import DATA, evaluate, operator_count, random_state

from rbdcgen.graph import expr as ex
from rbdcgen.commands import flops_report
from rbdcgen.views.scalar import TracedModel
from rbdcgen.backend.emit import emit_body
from rbdcgen.graph.flops import count_ops, generic_ops
from rbdcgen.frontend.ir import load_ir
from rbdcgen.commands.pipeline import Compilation
from rbdcgen.graph.manifold import configuration_seeds, integrate, q_direction
from rbdcgen.frontend.scene import CONTACT_DERIVATIVES, DERIVATIVES, SceneError, default_scene, load_scene, scene_from_dict
from rbdcgen.passes.trace import trace_function
from rbdcgen.passes.schedule import trace_scene

STEP = 1e-6
# Central differences: truncation h² ~ 1e-12 and round-off ε/h ~ 1e-10, relative to the largest entry.
TOLERANCE = 2e-7
# The Mini Cheetah's light legs make accelerations large next to their derivatives: round-off
# ε·|a|/h reaches ~3e-7 there (verify and the dual-number test check it to 1e-10 and 1e-12).
MINI_CHEETAH_TOLERANCE = 1e-6
FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
ALL = scene_from_dict({"name": "d", "derivatives": list(DERIVATIVES)})

# derivative function → [(output, primal function, primal output, input differentiated)]
CASES = {
    "inverse_dynamics_derivatives": [("dtau_dq", "inverse_dynamics", "tau", "q"),
                                     ("dtau_dv", "inverse_dynamics", "tau", "v")],
    "bias_derivatives": [("dbias_dq", "inverse_dynamics", "tau", "q"),
                         ("dbias_dv", "inverse_dynamics", "tau", "v")],
    "gravity_derivatives": [("dg_dq", "gravity_terms", "g", "q")],
    "forward_dynamics_derivatives": [("da_dq", "forward_dynamics", "a", "q"),
                                     ("da_dv", "forward_dynamics", "a", "v"),
                                     ("da_dtau", "forward_dynamics", "a", "tau"),
                                     ("da_df", "forward_dynamics", "a", "f")],
    "feet_velocity_derivatives": [("dpdot_dq", "feet_velocities", "pdot", "q")],
    "feet_force_term_derivatives": [("dtau_e_dq", "feet_force_terms", "tau_e", "q")],
}


def stepped(robot, state, name, k, h):
    """The state with input `name` moved by h along direction k (q on the manifold)."""
    moved = {key: list(value) for key, value in state.items()}
    if name == "q":
        delta = [0.0] * robot.nv
        delta[k] = h
        moved["q"] = integrate(robot, state["q"], delta)
    else:
        moved[name][k] += h
    return moved


def central_difference(robot, primal, output, state, name):
    """Column-major Jacobian of primal's output with respect to input `name`."""
    size = robot.nv if name in ("q", "v") else len(state[name])
    columns = []
    for k in range(size):
        plus = evaluate(primal, stepped(robot, state, name, k, STEP))[output]
        minus = evaluate(primal, stepped(robot, state, name, k, -STEP))[output]
        columns += [(p - m) / (2 * STEP) for p, m in zip(plus, minus)]
    return columns


def relative_error(got, want):
    scale = max([1.0] + [abs(x) for x in want])
    return max([0.0] + [abs(g - w) for g, w in zip(got, want)]) / scale


class TangentsEqualFiniteDifferences(unittest.TestCase):
    def check_robot(self, robot, seeds=(1, 2)):
        nf = len(robot.feet)
        for seed in seeds:
            state = random_state(robot, nf, seed)
            for name, cases in CASES.items():
                got = evaluate(trace_function(robot, ALL, name), state)
                for output, primal_name, primal_output, wrt in cases:
                    # c + g is inverse dynamics at a = 0 (bias_derivatives has no input a)
                    at = dict(state, a=[0.0] * robot.nv) if name == "bias_derivatives" else state
                    primal = trace_function(robot, ALL, primal_name)
                    want = central_difference(robot, primal, primal_output, at, wrt)
                    with self.subTest(robot=robot.name, output=output, seed=seed):
                        self.assertEqual(len(got[output]), len(want))
                        self.assertLess(relative_error(got[output], want), TOLERANCE)

    def test_floating_base(self):
        self.check_robot(FLOATING)

    def test_fixed_base(self):
        self.check_robot(FIXED)

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_mini_cheetah_forward_dynamics(self):
        robot = mini_cheetah.load("floating")
        state = random_state(robot, len(robot.feet), 7)
        got = evaluate(trace_function(robot, ALL, "forward_dynamics_derivatives"), state)
        primal = trace_function(robot, ALL, "forward_dynamics")
        for output, wrt in (("da_dq", "q"), ("da_dv", "v")):
            want = central_difference(robot, primal, "a", state, wrt)
            self.assertLess(relative_error(got[output], want), MINI_CHEETAH_TOLERANCE, output)


class AnalyticRecursionsEqualTangents(unittest.TestCase):
    """The analytic recursions (algorithms/rnea_derivatives.py, feet_force_derivatives.py) equal the
    tangents of the traced primal (differentiate.propagate, the method kept for robots with rotors) to
    round-off: two independent derivations inside the generator, floating and fixed base."""

    def check_robot(self, robot, seed=3):
        from rbdcgen.passes import differentiate
        from rbdcgen.graph import spatial as sp
        from rbdcgen.algorithms import rnea
        from rbdcgen.algorithms.feet_force_derivatives import feet_force_term_derivatives
        state = random_state(robot, len(robot.feet), seed)
        with ex.Graph():
            m = TracedModel(robot, ALL)
            zero = sp.zeros(6)
            pairs = [(differentiate.inverse_dynamics_derivatives(m),
                      differentiate.q_and_v(m, rnea.inverse_dynamics(m), "dtau_dq", "dtau_dv")),
                     (differentiate.bias_derivatives(m),
                      differentiate.q_and_v(m, rnea.rnea(m, rnea.base_acceleration(m, zero), None, True),
                                           "dbias_dq", "dbias_dv"))]
            if robot.feet:
                tangents = differentiate.jacobian_columns(rnea.feet_force_terms(m), configuration_seeds(m),
                                                        [q_direction(k) for k in range(robot.nv)])
                rows = feet_force_term_derivatives(m)
                analytic = [rows[r][c] for c in range(robot.nv) for r in range(robot.nv)]
                pairs.append(({"dtau_e_dq": analytic}, {"dtau_e_dq": tangents}))
            for analytic, tangent in pairs:
                for name in tangent:
                    got = ex.evaluate(list(analytic[name]), state)
                    want = ex.evaluate(list(tangent[name]), state)
                    with self.subTest(robot=robot.name, output=name):
                        self.assertLess(relative_error(got, want), 1e-12)

    def test_floating_base(self):
        self.check_robot(FLOATING)

    def test_fixed_base(self):
        self.check_robot(FIXED)

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_mini_cheetah(self):
        self.check_robot(mini_cheetah.load("floating"))


class ManifoldSeeding(unittest.TestCase):
    def test_seeds_are_the_derivative_of_the_step(self):
        """Quaternion and position seeds equal d(q ⊕ tδ)/dt; the seeded rotation entries equal the
        derivative of R(q ⊕ tδ)."""
        robot = FLOATING
        state = random_state(robot, 2, 3)
        with ex.Graph():
            m = TracedModel(robot, default_scene())
            seeds = configuration_seeds(m)
            rotation = [x for row in m.base_rotation() for x in row]
            for k in range(robot.nv):
                tangent = [seeds.get(node.id, {}).get(q_direction(k), ex.const(0.0))
                           for node in list(m.q) + rotation]
                got = ex.evaluate(tangent, state)
                plus = stepped(robot, state, "q", k, STEP)
                minus = stepped(robot, state, "q", k, -STEP)
                want = [(p - n) / (2 * STEP) for p, n in zip(plus["q"], minus["q"])]
                want += [(p - n) / (2 * STEP) for p, n in zip(ex.evaluate(rotation, plus),
                                                               ex.evaluate(rotation, minus))]
                with self.subTest(direction=k):
                    self.assertLess(relative_error(got, want), 1e-8)

    def test_the_step_keeps_a_unit_quaternion_and_orders_like_v(self):
        state = random_state(FLOATING, 2, 4)
        q = integrate(FLOATING, state["q"], [0.3, -0.2, 0.1, 1.0, 0.0, 0.0] + [0.5] * 3)
        self.assertAlmostEqual(sum(x * x for x in q[3:7]), 1.0, places=14)
        self.assertEqual(q[7:], [x + 0.5 for x in state["q"][7:]])
        moved = integrate(FLOATING, state["q"], [0.0] * 3 + [1.0, 0.0, 0.0] + [0.0] * 3)
        self.assertEqual(moved[3:], state["q"][3:])    # δp leaves orientation and joints alone


class Counts(unittest.TestCase):
    def test_emitted_operations_are_counted_and_fewer_than_the_runtime_tangent_passes(self):
        for name in DERIVATIVES:
            fn = trace_function(FLOATING, ALL, name)
            with self.subTest(function=name):
                total = sum(operator_count(line) for line in emit_body(fn))
                self.assertEqual(total, count_ops(fn)["total"])
                self.assertLess(count_ops(fn)["total"], generic_ops(FLOATING, ALL, name)["total"])

    def test_rbdc_flops_compares_each_derivative_with_its_primal(self):
        scene = scene_from_dict({"name": "x", "quantities": ["gravity_terms"],
                                 "derivatives": ["gravity_derivatives"]})
        functions = trace_scene(FLOATING, scene)
        compilation = Compilation(robot=FLOATING, scene=scene, functions=functions,
                                  robot_name="tiny", inputs=[], robot_inputs=[])
        rows = flops_report.rows(compilation)
        self.assertNotIn("primal", rows[0])
        self.assertEqual(rows[1]["primal"], {"function": "gravity_terms",
                                             "ops": count_ops(functions[0])})
        ratio = count_ops(functions[1])["total"] / count_ops(functions[0])["total"]
        self.assertIn("%.1fx gravity_terms" % ratio, flops_report.table(compilation, rows))
        as_json = flops_report.as_json(compilation, rows)["functions"]["gravity_derivatives"]
        self.assertEqual(as_json["primal"]["function"], "gravity_terms")


class Scenes(unittest.TestCase):
    def test_only_the_listed_derivatives_are_emitted_after_the_quantities(self):
        scene = scene_from_dict({"name": "x", "quantities": ["gravity_terms"],
                                 "derivatives": ["gravity_derivatives"]})
        self.assertEqual([f.name for f in trace_scene(FLOATING, scene)],
                         ["gravity_terms", "gravity_derivatives"])
        self.assertEqual([f.name for f in trace_scene(FLOATING, scene_from_dict({"name": "x"}))
                          if f.name.endswith("_derivatives")], [])

    def test_the_bundled_derivatives_scene_asks_for_every_derivative(self):
        """Every one but the contact dynamics', which the contact scene asks for."""
        scene = load_scene(os.path.join(SCENES, "derivatives.yaml"))
        self.assertEqual(scene.derivatives_for(FLOATING),
                         tuple(d for d in DERIVATIVES if d not in CONTACT_DERIVATIVES))
        self.assertEqual(load_scene(os.path.join(SCENES, "contact.yaml")).derivatives_for(FLOATING),
                         CONTACT_DERIVATIVES)
        self.assertIn("inverse_dynamics", scene.quantities_for(FLOATING))

    def test_bad_derivative_lists_are_refused(self):
        with self.assertRaises(SceneError) as caught:
            scene_from_dict({"name": "x", "derivatives": ["hessian"]}, source="s.yaml")
        self.assertIn("hessian", str(caught.exception))
        no_feet = load_ir(os.path.join(DATA, "tiny_fixed.json"))
        scene = scene_from_dict({"name": "x", "feet": [], "derivatives": ["feet_velocity_derivatives"]},
                                source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.derivatives_for(no_feet)
        self.assertIn("no feet", str(caught.exception))

    def test_a_zero_velocity_folds_the_velocity_derivative_away(self):
        """c is quadratic in v, so at v = 0 its derivative vanishes: the input and all its work go."""
        scene = scene_from_dict({"name": "x", "zero_inputs": ["v"],
                                 "derivatives": ["inverse_dynamics_derivatives"]})
        fn = trace_function(FLOATING, scene, "inverse_dynamics_derivatives")
        self.assertEqual([a.name for a in fn.inputs], ["q", "a"])
        self.assertTrue(all(x.is_const(0.0) for x in fn.values["dtau_dv"]))
        self.assertLess(count_ops(fn)["total"],
                        count_ops(trace_function(FLOATING, ALL, "inverse_dynamics_derivatives"))["total"])


if __name__ == "__main__":
    unittest.main()
