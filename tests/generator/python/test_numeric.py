"""Traced functions evaluated over their DAG equal the independent Python reference
(reference.py) on the small fixture robots, floating and fixed base, several random states."""

import os
import unittest

from numeric_check import DATA, evaluate, flatten_columns, flatten_matrix, max_relative_error, \
    random_state
from reference import Reference

from rbdcgen.ir import load_ir
from rbdcgen.scene import default_scene
from rbdcgen.trace import trace_function

TOLERANCE = 1e-12
# The reference inverts the mass matrix augmented by ground masses up to 1e4 kg; its condition
# number, not the traced code, limits the agreement there.
CLOSED_CHAIN_TOLERANCE = 1e-10
SEEDS = (1, 2, 3)


def expected(ref, name, s, nf):
    q, v, a, tau = s["q"], s["v"], s["a"], s["tau"]
    forces = [s["f"][3 * k:3 * k + 3] for k in range(nf)]
    if name == "feet_positions":
        return {"p": flatten_columns(ref.feet_positions(q))}
    if name == "feet_velocities":
        return {"pdot": flatten_columns(ref.feet_velocities(q, v))}
    if name == "feet_jacobian":
        return {"J": flatten_matrix(ref.feet_jacobian(q))}
    if name == "quadratic_velocity_terms":
        return {"c": ref.quadratic_velocity_terms(q, v)}
    if name == "gravity_terms":
        return {"g": ref.gravity_terms(q)}
    if name == "feet_force_terms":
        return {"tau_e": ref.feet_force_terms(q, forces)}
    if name == "inverse_dynamics":
        return {"tau": ref.inverse_dynamics(q, v, a)}
    if name == "mass_matrix":
        return {"M": flatten_matrix(ref.mass_matrix(q))}
    if name == "forward_dynamics":
        return {"a": ref.forward_dynamics(q, v, tau, forces)}
    if name == "osc_open_chain":
        Lam, JbarT, b = ref.osc_open_chain(q, v, forces)
    elif name == "osc_closed_chain":
        Lam, JbarT, b = ref.osc_closed_chain(q, v, s["ground_mass"][0])
    else:
        raise KeyError(name)
    return {"Lambda": flatten_matrix(Lam), "JbarT": flatten_matrix(JbarT), "b": b}


class TracedEqualsReference(unittest.TestCase):
    def check_robot(self, path):
        robot = load_ir(os.path.join(DATA, path))
        scene = default_scene()
        ref = Reference(robot)
        nf = len(robot.feet)
        for name in scene.quantities_for(robot):
            fn = trace_function(robot, scene, name)
            for seed in SEEDS:
                state = random_state(robot, nf, seed)
                got = evaluate(fn, state)
                want = expected(ref, name, state, nf)
                for key, values in want.items():
                    with self.subTest(robot=path, function=name, output=key, seed=seed):
                        self.assertEqual(len(got[key]), len(values))
                        tolerance = (CLOSED_CHAIN_TOLERANCE if name == "osc_closed_chain"
                                     else TOLERANCE)
                        self.assertLess(max_relative_error(got[key], values), tolerance)

    def test_floating_base(self):
        self.check_robot("tiny_floating.json")

    def test_fixed_base(self):
        self.check_robot("tiny_fixed.json")


if __name__ == "__main__":
    unittest.main()
