"""The singular-mass-matrix rule (docs/model.md, "Singular mass matrix"), as the runtime applies it
(rbdc::mass_matrix_singularity): M at one generic configuration, factored M = Lᵀ D L from the last
dof to the first as the generated factor is, is singular when a pivot D_k ≤ 1e-12 · M_kk. The
functions that need M⁻¹ (NEEDS_INVERSE) are then left out of a default scene and refused when a
scene asks for them (applicable), while kinematics and inverse dynamics are generated as usual."""
from __future__ import annotations

import functools
import math
import sys

from ..frontend.scene import default_scene
from .trace import trace_function

SINGULAR_PIVOT = 1e-12
NEEDS_INVERSE = ("mass_matrix_factor", "forward_dynamics", "step_terms", "osc_open_chain",
                 "osc_closed_chain", "forward_dynamics_lanes", "osc_open_chain_lanes",
                 "forward_dynamics_derivatives", "forward_dynamics_derivatives_lanes",
                 "mass_matrix_inverse", "contact_dynamics", "impulse_dynamics",
                 "contact_dynamics_derivatives")
GENERIC_CAUSE = "its motion moves no inertia that the dofs after it cannot move as well"


def generic_configuration(robot):
    """Floating base at the identity (w x y z = 1 0 0 0), joint entry k of q at sin(k + 1)."""
    base = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0] if robot.floating_base else []
    return base + [math.sin(k + 1.0) for k in range(robot.nq - len(base))]


def _dof_label(robot, k):
    """The dof's joint, and why it moves no inertia of its own (as the runtime says it)."""
    bodies = [i for i in range(1, robot.nb) if robot.joints[i].v_index == k]
    if k < robot.root_dofs or not bodies:
        return "%s %d" % ("floating-base dof" if k < robot.root_dofs else "dof", k), GENERIC_CAUSE
    i = bodies[0]
    body = robot.bodies[i]
    leaf = not robot.children[i] and body.mass == 0 and not any(any(row) for row in body.inertia_com)
    return ("joint '%s' (dof %d)" % (robot.joints[i].name, k),
            "body '%s' is a moving leaf with zero mass" % body.name if leaf else GENERIC_CAUSE)


@functools.lru_cache(maxsize=None)
def singularity(robot):
    """Why the robot's M is singular by the rule, or None when it is positive definite."""
    M = trace_function(robot, default_scene(), "mass_matrix",
                       known_inputs={"q": generic_configuration(robot)}).values["M"]
    n = robot.nv
    assert all(x.op == "const" for x in M), "mass_matrix at a known q should fold to constants"
    flat = [x.value for x in M]
    H = [[flat[c * n + r] for c in range(n)] for r in range(n)]   # the output is column-major
    diagonal = [H[k][k] for k in range(n)]
    for k in range(n - 1, -1, -1):
        if not H[k][k] > SINGULAR_PIVOT * diagonal[k]:
            label, cause = _dof_label(robot, k)
            return ("the mass matrix is singular: %s has pivot %.6g ≤ %g · M_kk = %.6g (%s)"
                    % (label, H[k][k], SINGULAR_PIVOT, SINGULAR_PIVOT * diagonal[k], cause))
        for i in range(k - 1, -1, -1):
            ratio = H[k][i] / H[k][k]
            for j in range(i + 1):
                H[i][j] -= ratio * H[k][j]
            H[k][i] = ratio
    return None


def applicable(robot, scene, names):
    """`names` without the functions that need M⁻¹ when the robot's M is singular: left out with a
    warning when the scene lists no quantities (all that apply), refused when it names them."""
    needing = [name for name in names if name in NEEDS_INVERSE]
    reason = singularity(robot) if needing else None
    if reason is None:
        return names
    for name in needing:
        if name in (scene.quantities or ()) or name in scene.derivatives:
            scene.fail("quantities" if name not in scene.derivatives else "derivatives",
                       "'%s' does not apply to robot '%s' (%s)" % (name, robot.name, reason))
    print("rbdc: warning: robot '%s': %s; left out: %s" % (robot.name, reason, ", ".join(needing)),
          file=sys.stderr)
    return tuple(name for name in names if name not in NEEDS_INVERSE)
