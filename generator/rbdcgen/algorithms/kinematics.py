"""Kinematics (paper 000 Alg. 1, Eqs. 9-19): body velocities and accelerations, world frames, feet
positions and velocities."""

from __future__ import annotations

from ..graph import spatial as sp


def body_velocities(m):
    """Alg. 1 line 7 (Eq. 13): v_i = X_λ(i)^i v_λ(i) + S_i q̇_i, v₀ the trunk twist."""
    velocities = [m.base_velocity()]
    for i in range(1, m.robot.nb):
        m.mark("outward pass, velocities", i)
        velocities.append(body_velocity(m, i, velocities[m.robot.parent[i]]))
    return velocities


def body_velocity(m, i, parent_velocity):
    """Eq. 13 for one body: v_i = X_λ(i)^i v_λ(i) + S_i q̇_i."""
    return sp.vadd(m.X_up(i).motion(parent_velocity), sp.vscale(m.vi(i), m.motion_subspace(i)))


def world_frames(m):
    """Eqs. 14-15 in rotation + position form: for each body the rotation R_i (body → world, =
    (R_W^i)ᵀ) and the world position p_i of its origin, composed outward joint by joint."""
    frames = [(m.base_rotation(), m.base_position())]
    for i in range(1, m.robot.nb):
        m.mark("world frames", i)
        R, p = frames[m.robot.parent[i]]
        for x in m.X_up(i).factors:
            if x.r is not None:
                p = sp.vadd(p, sp.matvec(R, x.r))
            if x.E is not None:
                R = sp.matmul(R, sp.transpose(x.E))
        frames.append((R, p))
    return frames


def feet_positions(m, frames=None):
    """Eqs. 16-18: p_fk = p_φ(k) + R_φ(k) r_fk (world coordinates)."""
    frames = frames or world_frames(m)
    result = []
    for foot in m.feet:
        m.mark("foot " + foot.name)
        R, p = frames[foot.body]
        result.append(sp.vadd(p, sp.matvec(R, sp.vec(foot.offset))))
    return result


def feet_velocities(m):
    """World linear velocity of each foot point: R_φ(k) (v_φ(k) + ω_φ(k) × r_fk), the linear part
    of X_i^fk v_i (Eq. 16) rotated to the world."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    result = []
    for foot in m.feet:
        m.mark("foot " + foot.name)
        v = velocities[foot.body]
        local = sp.vadd(sp.lin(v), sp.cross(sp.ang(v), sp.vec(foot.offset)))
        result.append(sp.matvec(frames[foot.body][0], local))
    return result


def feet_angular_velocities(m):
    """World angular velocity of each foot's body: R_φ(k) ω_φ(k)."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    result = []
    for foot in m.feet:
        m.mark("foot " + foot.name)
        result.append(sp.matvec(frames[foot.body][0], sp.ang(velocities[foot.body])))
    return result


def body_accelerations(m, velocities, base, with_joint_accelerations=False):
    """Each body's spatial acceleration in its coordinates from the trunk's `base` (Eq. 19):
    a_i = X_λ(i)^i a_λ(i) + v_i × S_i q̇_i (+ S_i q̈_i with the joint accelerations)."""
    accelerations = [base]
    phase = "outward pass, " + ("accelerations" if with_joint_accelerations else "velocity-product accelerations")
    for i in range(1, m.robot.nb):
        m.mark(phase, i)
        S = m.motion_subspace(i)
        a_i = sp.vadd(m.X_up(i).motion(accelerations[m.robot.parent[i]]),
                      sp.crm(velocities[i], sp.vscale(m.vi(i), S)))
        if with_joint_accelerations:
            a_i = sp.vadd(a_i, sp.vscale(m.ai(i), S))
        accelerations.append(a_i)
    return accelerations
