"""Tangent directions of the configuration: what ∂/∂q means (docs/conventions.md, "Derivatives").

A derivative with respect to q is one with respect to a tangent δ ∈ R^nv applied as q ⊕ δ. For a
floating base, q = (p, quaternion w x y z, joints) and δ = (δθ, δp, δq_joints) ordered like
v = (ω, v, q̇) (the runtime's rbdc/manifold.hpp is the same step):
    p' = p + R δp,    R' = R exp(δθ^),    q_j' = q_j + δq_j
so along δp_k the position moves by R e_k, along δθ_k the quaternion by ½ q ⊗ (0, e_k) and the
rotation matrix by R ê_k. A fixed base has plain partial derivatives.

The seeds returned here are what derivatives.propagate starts from: {node id: {direction:
tangent}}. The rotation matrix R = base_rotation() is seeded directly with R ê_k (its entries,
signed: no operation) as well as the quaternion symbols it is built from; propagation takes a
seeded node's tangent as given, so everything downstream of R gets the cheap exact tangent. Both
agree on unit quaternions (the curve q ⊗ exp(tθ/2) stays on the sphere where R(q) is exact).
"""

from __future__ import annotations

import math

from . import expr as ex
from . import spatial as sp


def q_direction(k):
    """Direction key of the k-th configuration tangent (k < nv)."""
    return ("q", k)


def v_direction(k):
    return ("v", k)


def _add(seeds, node, direction, tangent):
    if node.op == "const":   # a zero input: nothing to seed
        return
    if not tangent.is_const(0.0):
        seeds.setdefault(node.id, {})[direction] = tangent


def configuration_seeds(m):
    """Seeds of the nv configuration tangents, keys q_direction(k), for a TracedModel `m` (or a
    LaneModel: nv of the reduced tree)."""
    robot = m.robot
    q = m.q
    seeds = {}
    if robot.floating_base:
        R = m.base_rotation()
        w, x, y, z = q[3:7]
        for k in range(3):
            for r in range(3):                      # δp_k: p' = p + R e_k
                _add(seeds, q[r], q_direction(3 + k), R[r][k])
            e = [0.0, 0.0, 0.0]
            e[k] = 1.0
            u = sp.vec(e)
            vector = sp.cross((x, y, z), u)         # ½ q ⊗ (0, e_k) = ½ (−v·e_k, w e_k + v × e_k)
            quaternion = [-sp.dot((x, y, z), u)] + [w * u[i] + vector[i] for i in range(3)]
            for node, value in zip((w, x, y, z), quaternion):
                _add(seeds, node, q_direction(k), ex.const(0.5) * value)
            R_hat = sp.matmul(R, sp.skew(u))        # δθ_k: R' = R (1 + ê_k): signed entries of R
            for r in range(3):
                for c in range(3):
                    _add(seeds, R[r][c], q_direction(k), R_hat[r][c])
    for i in range(1, robot.nb):  # m.qi: a lane symbol on the lane model (lane k's own tangent)
        _add(seeds, m.qi(i), q_direction(robot.joints[i].v_index), ex.const(1.0))
    return seeds


def velocity_seeds(m):
    """Seeds of the nv velocity directions, keys v_direction(k): plain partials."""
    return {node.id: {v_direction(k): ex.const(1.0)}
            for k, node in enumerate(m.tree_velocity) if node.op != "const"}


def integrate(robot, q, delta):
    """q ⊕ δ in floats (tests and finite differences): the exact manifold step above."""
    q = list(q)
    if not robot.floating_base:
        return [a + b for a, b in zip(q, delta)]
    w, x, y, z = q[3:7]
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    out = list(q)
    for r in range(3):
        out[r] = q[r] + sum(R[r][c] * delta[3 + c] for c in range(3))
    theta = delta[0:3]
    angle = math.sqrt(sum(t * t for t in theta))
    if angle > 0.0:
        s = math.sin(0.5 * angle) / angle
        dw, dx, dy, dz = math.cos(0.5 * angle), theta[0] * s, theta[1] * s, theta[2] * s
    else:
        dw, dx, dy, dz = 1.0, 0.0, 0.0, 0.0
    out[3:7] = [w * dw - x * dx - y * dy - z * dz,          # q ⊗ exp(δθ/2)
                w * dx + x * dw + y * dz - z * dy,
                w * dy - x * dz + y * dw + z * dx,
                w * dz + x * dy - y * dx + z * dw]
    for k in range(6, robot.nv):
        out[k + 1] = q[k + 1] + delta[k]
    return out
