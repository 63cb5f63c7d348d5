"""The traced contact functions (algorithms/contact_dynamics.py) on the tiny floating robot, checked
with other traced functions: the first KKT row M a + c + g − Sᵀτ − Jᵀλ = 0 (inverse dynamics and
feet_force_terms), the impact law J v⁺ = −e J v⁻ (the feet Jacobian); and the scene's refusals."""

import os
import unittest

from numeric_check import DATA, evaluate, max_relative_error, random_state
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import SceneError, scene_from_dict
from rbdcgen.passes.trace import trace_function

ROBOT = load_ir(os.path.join(DATA, "tiny_floating.json"))


def matvec(J, rows, cols, x):
    """J (column-major rows × cols) times x."""
    return [sum(J[c * rows + r] * x[c] for c in range(cols)) for r in range(rows)]


class ContactDynamics(unittest.TestCase):
    scene = scene_from_dict({"name": "x"})

    def run_function(self, name, state):
        return evaluate(trace_function(ROBOT, self.scene, name), state)

    def test_kkt_rows_and_impact_law(self):
        nv, nf = ROBOT.nv, len(ROBOT.feet)
        state = random_state(ROBOT, nf, 3)
        out = self.run_function("contact_dynamics", state)
        a, lam = out["a"], out["lambda"]
        self.assertGreater(max(map(abs, lam)), 1e-3)
        # row 1 with the traced RNEA and Alg. 4: τ_ID(a) − Sᵀτ − Jᵀλ = 0
        tau_id = self.run_function("inverse_dynamics", {**state, "a": a})["tau"]
        tau_e = self.run_function("feet_force_terms", {**state, "f": lam})["tau_e"]
        root = nv - ROBOT.n_joints
        residual = [t - e - (0.0 if k < root else state["tau"][k - root])
                    for k, (t, e) in enumerate(zip(tau_id, tau_e))]
        self.assertLess(max(map(abs, residual)) / max(1.0, max(map(abs, tau_id))), 1e-10)
        # (row 2, J a + J̇v = 0, is checked by the runtime's tests and by rbdc verify against them)
        J = self.run_function("feet_jacobian", state)["J"]
        v = state["v"]
        # impulse: J v⁺ = −e J v⁻
        impact = self.run_function("impulse_dynamics", {**state, "restitution": [0.3]})
        Jv_plus = matvec(J, 3 * nf, nv, impact["v_plus"])
        Jv_minus = matvec(J, 3 * nf, nv, v)
        self.assertLess(max_relative_error(Jv_plus, [-0.3 * x for x in Jv_minus]), 1e-10)


class Refusals(unittest.TestCase):
    def test_an_empty_contact_set_is_refused(self):
        scene = scene_from_dict({"name": "x", "contacts": [], "quantities": ["contact_dynamics"]},
                                source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.quantities_for(ROBOT)
        self.assertIn("no contacts", str(caught.exception))
        scene = scene_from_dict({"name": "x", "contacts": [],
                                 "derivatives": ["contact_dynamics_derivatives"]}, source="s.yaml")
        with self.assertRaises(SceneError) as caught:
            scene.derivatives_for(ROBOT)
        self.assertIn("contact_dynamics_derivatives", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
