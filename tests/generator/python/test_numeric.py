"""Traced functions evaluated over their DAG equal the independent Python reference
(reference.py) on the small fixture robots, floating and fixed base, several random states."""

import os
import unittest

import mini_cheetah
from numeric_check import DATA, evaluate, flatten_columns, flatten_matrix, max_relative_error, \
    random_state
from reference import Reference, constrained_osc, ltdl

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene, scene_from_dict
from rbdcgen.passes.trace import trace_function

TOLERANCE = 1e-12
# The reference inverts the mass matrix augmented by ground masses up to 1e3 kg; its condition
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
    if name == "bias":
        return {"cg": ref.inverse_dynamics(q, v, [0.0] * len(v))}
    if name == "mass_matrix":
        return {"M": flatten_matrix(ref.mass_matrix(q))}
    if name == "mass_matrix_factor":
        L, D = ltdl(ref.mass_matrix(q))
        return {"L": flatten_matrix(L), "D": D, "D_inv": [1.0 / d for d in D]}
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
    def check_robot(self, path, robot=None, seeds=SEEDS):
        robot = robot or load_ir(os.path.join(DATA, path))
        scene = default_scene()
        ref = Reference(robot)
        nf = len(robot.feet)
        for name in scene.quantities_for(robot):
            fn = trace_function(robot, scene, name)
            for seed in seeds:
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

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_mini_cheetah(self):
        self.check_robot("mini_cheetah", mini_cheetah.load("floating"), seeds=(11,))
        self.check_robot("mini_cheetah (fixed base)", mini_cheetah.load("fixed"), seeds=(12,))


class SceneSubsets(unittest.TestCase):
    def test_kept_feet_and_contacts_subsets(self):
        robot = load_ir(os.path.join(DATA, "tiny_floating.json"))
        scene = scene_from_dict({"name": "x", "feet": ["slider_foot", "lower_foot"],
                                 "contacts": ["slider_foot"]})
        state = random_state(robot, 2, 9)
        got = evaluate(trace_function(robot, scene, "osc_closed_chain"), state)
        ref = Reference(robot)
        Lam, JbarT, b = ref.osc_closed_chain(state["q"], state["v"], state["ground_mass"][0],
                                             contacts=[robot.foot("slider_foot")])
        self.assertLess(max_relative_error(got["Lambda"], flatten_matrix(Lam)), 1e-10)
        self.assertLess(max_relative_error(got["b"], b), 1e-10)
        one_foot = scene_from_dict({"name": "x", "feet": ["slider_foot"]})
        state = random_state(robot, 1, 10)
        got = evaluate(trace_function(robot, one_foot, "feet_jacobian"), state)
        want = Reference(robot, feet=[robot.foot("slider_foot")]).feet_jacobian(state["q"])
        self.assertLess(max_relative_error(got["J"], flatten_matrix(want)), TOLERANCE)


class BigGroundInertiaLimit(unittest.TestCase):
    """Paper 001 App. A: with a very large ground mass the closed-chain recursion tends to the
    exactly constrained operational-space quantities (Eqs. 20-24). Needs a robot whose trunk stays
    free with every foot pinned (three joints per leg): the Mini Cheetah."""

    @unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
    def test_closed_chain_tends_to_the_constrained_dynamics(self):
        robot = mini_cheetah.load()
        fn = trace_function(robot, default_scene(), "osc_closed_chain")
        state = random_state(robot, len(robot.feet), 5)
        Lam, JtildeT = constrained_osc(Reference(robot), state["q"])
        errors = {}
        for mass in (1e2, 1e8):
            state["ground_mass"] = [mass]
            got = evaluate(fn, state)
            errors[mass] = (max_relative_error(got["Lambda"], flatten_matrix(Lam)),
                            max_relative_error(got["JbarT"], flatten_matrix(JtildeT)))
        self.assertLess(max(errors[1e8]), 1e-5)
        self.assertGreater(max(errors[1e2]), 100 * max(errors[1e8]))

if __name__ == "__main__":
    unittest.main()
