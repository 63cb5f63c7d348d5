"""Properties of the traced dynamics on random robots of every kind (frontend/random_robot.py): the
plain ones (revolute, continuous, prismatic, fixed joints merged), massless bodies anywhere, masses
over twelve decades with near-singular inertias, mimic joints; floating and fixed bases. For a finite
state nothing is NaN; M is symmetric and, where the model is regular, positive definite; inverse
dynamics undoes forward dynamics: ID(q, v, FD(q, v, τ)) = (0, τ). Against the runtime the same kinds
are checked by `rbdc verify` (verify_random_robots.py). The singular-mass rule's O(n) pivots (the
articulated inertias) give the verdict of factoring M itself, dof and pivot."""

import json
import math
import os
import subprocess
import tempfile
import unittest

import numpy

from mini_cheetah import model_tool, skip_reason
from numeric_check import evaluate, random_state
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.random_robot import random_urdf
from rbdcgen.frontend.scene import Scene
from rbdcgen.passes import singular_mass
from rbdcgen.passes.singular_mass import singularity
from rbdcgen.passes.trace import trace_function

SEEDS = range(6)
KINDS = {"plain": {}, "massless": {"massless": True}, "extremes": {"extremes": True}, "mimic": {"mimic": True}}
# ID(FD(τ)) relative to the largest generalised force. Measured worst over these seeds: plain 1.5e-14,
# massless 1.8e-14 (five regular robots), mimic 2.0e-14, extremes 7.8e-10 (masses over twelve decades
# condition M up to ~1e12).
TOLERANCE = {"plain": 1e-10, "massless": 1e-10, "extremes": 1e-7, "mimic": 1e-10}


def load(urdf_text, base):
    with tempfile.NamedTemporaryFile("w", suffix=".urdf", delete=False) as handle:
        handle.write(urdf_text)
    try:
        result = subprocess.run([model_tool(), handle.name, "--%s-base" % base], capture_output=True,
                                text=True, check=True)
    finally:
        os.unlink(handle.name)
    return load_ir(json.loads(result.stdout))


@unittest.skipIf(skip_reason(), skip_reason())
class RandomRobotProperties(unittest.TestCase):
    def check(self, kind, seed):
        base = "floating" if seed % 2 == 0 else "fixed"
        robot = load(random_urdf(seed, max_links=8, **KINDS[kind]), base)
        scene = Scene(base=base)
        state = random_state(robot, len(robot.feet), seed)
        nv, root = robot.nv, robot.root_dofs
        M = numpy.array(evaluate(trace_function(robot, scene, "mass_matrix"), state)["M"]).reshape(nv, nv).T
        where = "%s seed %d (%s base, nv %d)" % (kind, seed, base, nv)
        self.assertTrue(numpy.isfinite(M).all(), where)
        self.assertLessEqual(numpy.abs(M - M.T).max(), 1e-12 * max(1.0, numpy.abs(M).max()), where)
        if singularity(robot) is not None:
            return  # the functions needing M⁻¹ are left out for such a robot (docs/model.md)
        # positive definite where the model says it is: Cholesky succeeds on M scaled to unit diagonal
        d = 1.0 / numpy.sqrt(numpy.diag(M))
        numpy.linalg.cholesky(M * numpy.outer(d, d))
        a = evaluate(trace_function(robot, scene, "forward_dynamics"), dict(state, f=[0.0] * 3 * len(robot.feet)))["a"]
        self.assertTrue(all(math.isfinite(x) for x in a), where)
        tau = evaluate(trace_function(robot, scene, "inverse_dynamics"), dict(state, a=a))["tau"]
        want = [0.0] * root + list(state["tau"])
        scale = max([1.0] + [abs(x) for x in tau] + [abs(x) for x in want])
        error = max(abs(x - y) for x, y in zip(tau, want)) / scale
        self.assertLess(error, TOLERANCE[kind], "%s: ID(FD(τ)) − (0, τ) = %.1e relative" % (where, error))

    def test_articulated_pivots_give_the_verdict_of_the_factored_mass_matrix(self):
        for kind in ("plain", "massless", "extremes"):  # mimic: the rule factors M (no articulated form)
            for seed in SEEDS:
                robot = load(random_urdf(seed, max_links=8, **KINDS[kind]), "floating" if seed % 2 == 0 else "fixed")
                articulated = singular_mass._articulated_small_pivot(robot)
                factored = singular_mass._factored_small_pivot(robot)
                with self.subTest(kind=kind, seed=seed, articulated=articulated, factored=factored):
                    self.assertEqual(articulated is None, factored is None)
                    if factored is not None:
                        self.assertEqual(articulated[0], factored[0])
                        self.assertAlmostEqual(articulated[1], factored[1], delta=1e-9 * max(1.0, factored[2]))

    def test_every_kind(self):
        for kind in KINDS:
            for seed in SEEDS:
                with self.subTest(kind=kind, seed=seed):
                    self.check(kind, seed)


if __name__ == "__main__":
    unittest.main()
