"""The singular-mass-matrix rule (docs/model.md, "Singular mass matrix"), as the runtime applies it
(rbdc::mass_matrix_singularity): M at one generic configuration, factored M = Lᵀ D L from the last
dof to the first as the generated factor is, is singular when a pivot D_k ≤ 1e-12 · M_kk. The
functions that need M⁻¹ (NEEDS_INVERSE) are then left out of a default scene and refused when a
scene asks for them (applicable), while kinematics and inverse dynamics are generated as usual.

On a tree without rotors or couplings the pivots come in O(n) from the articulated inertias (a dof's
pivot of the leaves-first factor is S_kᵀ I^A_k S_k, the articulated-body algorithm's D_k; M_kk is
S_kᵀ I^c_k S_k): forming M is O(n²) and factoring it O(n³), minutes of a 200-body chain's generation."""
from __future__ import annotations

import functools
import math
import sys

from ..algorithms.aba import applies as articulated_pivots_apply
from ..algorithms.crba import depth_first_order
from ..frontend.scene import default_scene
from ..graph.spatial import inertia_at_origin, snap_axis
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
    small = (_articulated_small_pivot if articulated_pivots_apply(robot) else _factored_small_pivot)(robot)
    if small is None:
        return None
    k, pivot, diagonal = small
    label, cause = _dof_label(robot, k)
    return ("the mass matrix is singular: %s has pivot %.6g ≤ %g · M_kk = %.6g (%s)"
            % (label, pivot, SINGULAR_PIVOT, SINGULAR_PIVOT * diagonal, cause))


def _first_small_pivot(H, diagonal, dofs):
    """Factors the symmetric H = Lᵀ D L from its last row to its first (in place); (dofs[k], pivot,
    diagonal[k]) for the first pivot D_k ≤ SINGULAR_PIVOT · diagonal[k], else None."""
    for k in range(len(H) - 1, -1, -1):
        if not H[k][k] > SINGULAR_PIVOT * diagonal[k]:
            return dofs[k], H[k][k], diagonal[k]
        for i in range(k - 1, -1, -1):
            ratio = H[k][i] / H[k][k]
            for j in range(i + 1):
                H[i][j] -= ratio * H[k][j]
            H[k][i] = ratio
    return None


def _factored_small_pivot(robot):
    """The rule on M itself, from its CRBA traced at the generic configuration."""
    M = trace_function(robot, default_scene(), "mass_matrix",
                       known_inputs={"q": generic_configuration(robot)}).values["M"]
    n = robot.nv
    assert all(x.op == "const" for x in M), "mass_matrix at a known q should fold to constants"
    flat = [x.value for x in M]
    H = [[flat[c * n + r] for c in range(n)] for r in range(n)]   # the output is column-major
    return _first_small_pivot(H, [H[k][k] for k in range(n)], list(range(n)))


def _articulated_small_pivot(robot):
    """The rule by the articulated inertias (module doc), dofs from the last to the first as the
    factor: each joint dof's pivot on the way in, then the floating trunk's 6 × 6 I^A_0 factored."""
    X = trace_function(robot, default_scene(), "body_transforms",
                       known_inputs={"q": generic_configuration(robot)}).values["X"]
    column = {body: k - 1 for k, body in enumerate(depth_first_order(robot))}  # body i's transform
    articulated = [_spatial_inertia(body) for body in robot.bodies]
    composite = [[row[:] for row in inertia] for inertia in articulated]
    for i in range(robot.nb - 1, 0, -1):
        joint = robot.joints[i]
        axis = list(snap_axis(joint.axis))
        S = axis + [0.0] * 3 if joint.type == "revolute" else [0.0] * 3 + axis
        armature = joint.actuator.armature if joint.actuator else 0.0
        U = _matvec(articulated[i], S)
        pivot = _dot(S, U) + armature
        diagonal = _dot(S, _matvec(composite[i], S)) + armature
        if not pivot > SINGULAR_PIVOT * diagonal:
            return joint.v_index, pivot, diagonal
        j = robot.parent[i]
        transform = _motion_transform([x.value for x in X[12 * column[i]:12 * column[i] + 12]])
        composite[j] = _plus(composite[j], _congruence(transform, composite[i]))
        if j != 0 or robot.floating_base:
            projected = [[articulated[i][r][c] - U[r] * U[c] / pivot for c in range(6)] for r in range(6)]
            articulated[j] = _plus(articulated[j], _congruence(transform, projected))
    if not robot.floating_base:
        return None
    return _first_small_pivot(articulated[0], [composite[0][k][k] for k in range(6)], list(range(6)))


def _spatial_inertia(body):
    """[Ī h̃; h̃ᵀ m1] at the body's origin, in floats (spatial.Inertia.dense)."""
    Ibar, m = inertia_at_origin(body), body.mass
    h = [m * c for c in body.com]
    skew = [[0.0, -h[2], h[1]], [h[2], 0.0, -h[0]], [-h[1], h[0], 0.0]]
    return ([list(Ibar[r]) + skew[r] for r in range(3)]
            + [[skew[c][r] for c in range(3)] + [m if r == c else 0.0 for c in range(3)] for r in range(3)])


def _motion_transform(values):
    """X = [E 0; −E r̃ E] from body_transforms' E (row-major) and r."""
    E = [values[0:3], values[3:6], values[6:9]]
    r = values[9:12]
    skew = [[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]]
    lower = [[-sum(E[a][k] * skew[k][b] for k in range(3)) for b in range(3)] for a in range(3)]
    return [E[a] + [0.0] * 3 for a in range(3)] + [lower[a] + E[a] for a in range(3)]


def _matvec(A, x):
    return [_dot(row, x) for row in A]


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _plus(A, B):
    return [[a + b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def _congruence(X, A):
    """Xᵀ A X."""
    AX = [[sum(A[r][k] * X[k][c] for k in range(6)) for c in range(6)] for r in range(6)]
    return [[sum(X[k][r] * AX[k][c] for k in range(6)) for c in range(6)] for r in range(6)]


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
