"""Feet Jacobian (paper 000 Alg. 6, App. B, Eq. B3): the block of joint j in the rows of foot k is
the linear part of X_j^fk S_j (Eq. B3) rotated to the world; only joints in the support κ(φ(k))
contribute. Written with world axes and lever arms, the cheapest form of the same product."""

from __future__ import annotations

from ..graph import spatial as sp
from .kinematics import feet_positions, world_frames


def point_jacobian_columns(m, frames, body, point):
    """World columns (angular, linear) of the motion of a point fixed to `body` at world position
    `point` (Eq. B3 in world axes): the trunk's ω_B as (R ω_B, R ω_B × (p − p_0)), its v_B as (0, R
    v_B), a revolute joint j of κ(body) as (a_j, a_j × (p − p_j)) with its world axis a_j, a
    prismatic one as (0, a_j); other columns zero."""
    robot = m.robot
    zero = sp.zeros(3)
    angular = [zero] * robot.nv
    linear = [zero] * robot.nv
    if robot.floating_base:
        R, p0 = frames[0]
        lever = sp.vsub(point, p0)
        Rt = sp.transpose(R)
        for c in range(3):
            angular[c] = Rt[c]
            linear[c] = sp.cross(Rt[c], lever)
            linear[3 + c] = Rt[c]
    for j in robot.support[body]:
        R_j, p_j = frames[j]
        axis = sp.matvec(R_j, sp.vec(m.axis(j)))
        col = m.joint(j).v_index
        if m.joint(j).type == "revolute":
            angular[col] = axis
            linear[col] = sp.cross(axis, sp.vsub(point, p_j))
        else:
            linear[col] = axis
    return angular, linear


def feet_jacobian(m):
    """J = [J_0; J_1; …] (3·n_feet × nv), world-frame foot velocities from v (conventions.md): the
    linear world columns of each foot point."""
    frames = world_frames(m)
    positions = feet_positions(m, frames)
    rows = []
    for foot, p_foot in zip(m.feet, positions):
        m.mark("Jacobian of foot " + foot.name)
        cols = point_jacobian_columns(m, frames, foot.body, p_foot)[1]
        for r in range(3):
            rows.append(tuple(col[r] for col in cols))
    return rows


def feet_angular_jacobian(m):
    """The angular rows of each foot's body (3·n_feet × nv, world): ω_φ(k) = J_ω,k v, the angular
    world columns of point_jacobian_columns (the trunk's R ω_B, each revolute joint's world axis)."""
    frames = world_frames(m)
    rows = []
    for foot in m.feet:
        m.mark("angular rows of foot " + foot.name)
        cols = point_jacobian_columns(m, frames, foot.body, frames[foot.body][1])[0]
        for r in range(3):
            rows.append(tuple(col[r] for col in cols))
    return rows
