"""Feet Jacobian (paper 000 Alg. 6, App. B, Eq. B3): the block of joint j in the rows of foot k is
the linear part of X_j^fk S_j (Eq. B3) rotated to the world; only joints in the support κ(φ(k))
contribute. Written with world axes and lever arms, the cheapest form of the same product."""

from __future__ import annotations

from ..graph import spatial as sp
from .kinematics import feet_positions, world_frames


def feet_jacobian(m):
    """J = [J_0; J_1; …] (3·n_feet × nv), world-frame foot velocities from v (conventions.md)."""
    robot = m.robot
    frames = world_frames(m)
    positions = feet_positions(m, frames)
    rows = []
    for foot, p_foot in zip(m.feet, positions):
        m.mark("Jacobian of foot " + foot.name)
        cols = [sp.zeros(3) for _ in range(robot.nv)]
        if robot.floating_base:
            R, p0 = frames[0]
            lever = sp.vsub(p_foot, p0)
            Rt = sp.transpose(R)
            for c in range(3):
                cols[c] = sp.cross(Rt[c], lever)   # ω_B enters as (R ω_B) × (p_f − p_0)
                cols[3 + c] = Rt[c]                # v_B enters as R v_B
        for j in robot.support[foot.body]:
            R_j, p_j = frames[j]
            axis = sp.matvec(R_j, sp.vec(m.axis(j)))
            if m.joint(j).type == "revolute":
                cols[m.joint(j).v_index] = sp.cross(axis, sp.vsub(p_foot, p_j))
            else:
                cols[m.joint(j).v_index] = axis
        for r in range(3):
            rows.append(tuple(col[r] for col in cols))
    return rows


def feet_angular_jacobian(m):
    """The angular rows of each foot's body (3·n_feet × nv, world): ω_φ(k) = J_ω,k v. The trunk's ω_B
    enters as R ω_B, a revolute joint j of the support as its world axis R_j a_j; the trunk's linear
    velocity and prismatic joints do not turn the body."""
    robot = m.robot
    frames = world_frames(m)
    rows = []
    for foot in m.feet:
        m.mark("angular rows of foot " + foot.name)
        cols = [sp.zeros(3) for _ in range(robot.nv)]
        if robot.floating_base:
            Rt = sp.transpose(frames[0][0])
            for c in range(3):
                cols[c] = Rt[c]
        for j in robot.support[foot.body]:
            if m.joint(j).type == "revolute":
                cols[m.joint(j).v_index] = sp.matvec(frames[j][0], sp.vec(m.axis(j)))
        for r in range(3):
            rows.append(tuple(col[r] for col in cols))
    return rows
