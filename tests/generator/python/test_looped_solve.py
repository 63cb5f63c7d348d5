"""The looped forms of forward_dynamics_derivatives and contact_dynamics_derivatives
(passes/looped_solve.py): their traced terms, solved by an independent route (M and the damped
Delassus matrix rebuilt from their factors, dense numpy solves, the proximal steps iterated), equal
the scalar tree's outputs; the scene's schedule forces them, `auto` picks by cost and says so, a
coupled robot's solve is in its independent coordinates. The emitted loop itself is checked against
the runtime by `rbdc verify` (arm7 and humanoid32 `derivatives`, whose `auto` picks it) and compiled
under nvcc."""

import os
import unittest

import numpy as np
from mini_cheetah import skip_reason
from numeric_check import DATA, evaluate, random_state
from test_coupling import GRIPPER, MIMIC_ACROSS_BRANCHES, MIMIC_CHAIN, MIMIC_FINGERS, load as load_coupled

from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import scene_from_dict
from rbdcgen.graph import expr as ex
from rbdcgen.algorithms.forward_dynamics import dof_ancestors
from rbdcgen.passes.schedule import scheduled_function

FLOATING = load_ir(os.path.join(DATA, "tiny_floating.json"))
FIXED = load_ir(os.path.join(DATA, "tiny_fixed.json"))
NAME = "forward_dynamics_derivatives"


def scene(schedule):
    return scene_from_dict({"name": "x", "derivatives": [NAME], "schedule": schedule})


def terms_of(fn, state):
    """{term: floats} of a looped function's traced part."""
    values = iter(ex.evaluate(fn.output_exprs(), state))
    return {arg.name: [next(values) if e is not None else 0.0 for e in fn.values[arg.name]]
            for arg in fn.solve.terms}


def tree_factor(solve, terms):
    """M's unit lower triangular factor L (M = Lᵀ D L) rebuilt from its packed entries."""
    factor = np.eye(solve.nv)  # entries at each dof's ancestors
    packed = iter(terms["L"])
    for i in range(solve.nv):
        for j in dof_ancestors(solve.parents, i):
            factor[i, j] = next(packed)
    return factor


def mass_matrix(solve, terms):
    """M = Lᵀ D L rebuilt from the packed tree factor."""
    factor = tree_factor(solve, terms)
    return factor.T @ np.diag(1.0 / np.array(terms["D_inv"])) @ factor


def split_blocks(blocks, solution):
    outputs, first = {}, 0
    for name, width in blocks:
        outputs[name] = list(solution[:, first:first + width].T.ravel())
        first += width
    return outputs


def solved_outputs(fn, state):
    """{output: column-major floats}: the looped form's terms, solved densely."""
    solve = fn.solve
    terms = terms_of(fn, state)
    rhs = np.array(terms["rhs"]).reshape(solve.nv, solve.columns)
    return split_blocks(solve.blocks, np.linalg.solve(mass_matrix(solve, terms), rhs))


def solved_contact_outputs(fn, state):
    """The same for contact_dynamics_derivatives: J = Zᵀ L from Z = L⁻ᵀJᵀ (and (D⁻¹Z)ᵀ checked against
    Z), ∂λ from five proximal steps on the damped Delassus matrix F = L D Lᵀ (rebuilt from L⁻ᵀ and
    D⁻¹L⁻¹) and A = F − μ1, ∂a = M⁻¹(Jᵀ∂λ − r₁)."""
    solve = fn.solve
    terms = terms_of(fn, state)
    n, m, c = solve.nv, solve.contact_rows, solve.columns
    mass = mass_matrix(solve, terms)
    R1, R2 = (np.array(terms[k]).reshape(rows, c) for k, rows in (("R1", n), ("R2", m)))
    Z = np.array(terms["Z"]).reshape(n, m)
    np.testing.assert_allclose(np.array(terms["Zt_D"]).reshape(m, n),
                               (np.diag(terms["D_inv"]) @ Z).T, rtol=1e-14, atol=1e-300)
    J = Z.T @ tree_factor(solve, terms)
    lower = np.linalg.inv(np.array(terms["F_U"]).reshape(m, -1)[:, :m].T)
    pivots = 1.0 / np.diag(np.array(terms["F_DL"]).reshape(m, -1)[:, :m])
    F = lower @ np.diag(pivots) @ lower.T
    A = F - terms["mu"][0] * np.eye(m)
    b = J @ np.linalg.solve(mass, R1) - R2
    dlambda = np.zeros_like(b)
    for _ in range(5):
        dlambda += np.linalg.solve(F, b - A @ dlambda)
    da = np.linalg.solve(mass, J.T @ dlambda - R1)
    return {**split_blocks(solve.blocks, da), **split_blocks(solve.lambda_blocks, dlambda)}


def max_error(want, got):
    worst = 0.0
    for output, values in want.items():
        scale = max(1.0, max(abs(x) for x in values))
        worst = max(worst, max(abs(g - w) for g, w in zip(got[output], values)) / scale)
    return worst


def assert_solved_equal(test, robot, scene_of, name, solved, tolerance=1e-12):
    """`name`'s looped form (the scene `scene_of` makes forcing it) solved by `solved` equals its
    scalar tree on two random states; returns both."""
    looped = scheduled_function(robot, scene_of("looped_solve"), name)
    scalar = scheduled_function(robot, scene_of("scalar"), name)
    test.assertIsNotNone(looped.solve)
    test.assertEqual(looped.outputs, scalar.outputs)
    for seed in (1, 2):
        state = random_state(robot, len(robot.feet), seed)
        test.assertLess(max_error(evaluate(scalar, state), solved(looped, state)), tolerance,
                        (robot.name, robot.floating_base, seed))
    return looped, scalar


class LoopedForwardDynamicsDerivatives(unittest.TestCase):
    def test_terms_solved_equal_the_scalar_tree(self):
        for robot in (FLOATING, FIXED):
            looped, scalar = assert_solved_equal(self, robot, scene, NAME, solved_outputs)
            self.assertIsNone(scalar.solve)
            self.assertEqual(looped.schedule, "looped solve, as the scene asks")

    def test_auto_picks_by_cost_and_says_so(self):
        fn = scheduled_function(FLOATING, scene("auto"), NAME)
        forms = r"(looped solve|scalar tree|looped RNEA derivatives|looped CRBA)"
        self.assertRegex(fn.schedule, r"^%s\b.*\d+ arithmetic instructions \(critical path \d+ cycles, cost \d+\), "
                                      r"(%s \d+ \(path \d+, cost \d+\)(, )?){3}$"
                         % (forms, forms))

    @unittest.skipIf(skip_reason(), skip_reason())
    def test_a_coupled_robot_solves_in_its_independent_coordinates(self):
        """Its terms are the projected ones (passes/project.py), its factor over the independent dofs'
        tree (views/coupled.py, dof_parents); solved, they equal its scalar tree."""
        for path, base in ((GRIPPER, "floating"), (MIMIC_CHAIN, "floating"), (MIMIC_FINGERS, "floating"),
                           (MIMIC_ACROSS_BRANCHES, "fixed")):
            robot = load_coupled(path, base)
            self.assertTrue(robot.couplings)
            assert_solved_equal(self, robot, scene, NAME, solved_outputs)


def contact_scene(schedule):
    return scene_from_dict({"name": "x", "derivatives": [CONTACT], "schedule": schedule})


CONTACT = "contact_dynamics_derivatives"


class LoopedContactDynamicsDerivatives(unittest.TestCase):
    def test_terms_solved_equal_the_scalar_tree(self):
        # tiny_fixed's two point feet give 6 contact rows on 3 dofs: a redundant contact set, whose
        # least-norm solution amplifies round-off (docs/generated_api.md), hence its looser bound
        for robot, tolerance in ((FLOATING, 1e-12), (FIXED, 1e-8)):
            assert_solved_equal(self, robot, contact_scene, CONTACT, solved_contact_outputs, tolerance)

if __name__ == "__main__":
    unittest.main()
