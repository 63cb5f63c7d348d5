"""Operational frames (docs/model.md, "Frames"; the runtime's runtime/src/frames.cpp): a frame F sits
on body i at the constant X_i^F = (E, r). Placements, velocities, Jacobians and J̇v of the scene's
frames, and the feet's J̇v (a foot is the frame (1, offset) whose outputs keep the linear world rows).
World quantities use the rotation + position form of kinematics.world_frames; the local ones
rotate them by R_F^Wᵀ = E R_iᵀ. Spatial vectors are (angular; linear)."""

from __future__ import annotations

from ..graph import spatial as sp
from .jacobian import point_jacobian_columns
from .kinematics import body_accelerations, body_velocities, world_frames
from .rnea import velocity_bias


def frame_pose(frame):
    """(E, r) of X_i^F as expressions, E snapped like every constant rotation; None when trivial."""
    rotation = sp.snap_rotation(frame.rotation)
    identity = all(rotation[r][c] == (1.0 if r == c else 0.0) for r in range(3) for c in range(3))
    return (None if identity else sp.mat(rotation),
            sp.vec(frame.translation) if any(frame.translation) else None)


def _rotate(E, a):
    return a if E is None else sp.matvec(E, a)


def _world_rotation(R_i, E):
    """R_F^W = R_i Eᵀ (frame → world)."""
    return R_i if E is None else sp.matmul(R_i, sp.transpose(E))


def _offset_point(p_i, R_i, r):
    return p_i if r is None else sp.vadd(p_i, sp.matvec(R_i, r))


def frame_placements(m):
    """p_F = p_i + R_i r, R_F^W = R_i Eᵀ (Eqs. 15-18 with X_i^F)."""
    frames = world_frames(m)
    rotations, positions = [], []
    for frame in m.frames:
        m.mark("placement of frame " + frame.name)
        R_i, p_i = frames[frame.body]
        E, r = frame_pose(frame)
        rotations.append(_world_rotation(R_i, E))
        positions.append(_offset_point(p_i, R_i, r))
    return rotations, positions


def _velocity_at(v_i, r):
    """(ω, v_O + ω × r): body i's twist at the frame origin, body axes."""
    w, u = sp.ang(v_i), sp.lin(v_i)
    return w, (u if r is None else sp.vadd(u, sp.cross(w, r)))


def frame_velocities(m):
    """v_F = X_i^F v_i (local) and (R_i ω, R_i v) (world-aligned), each (angular; linear)."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    local, world = [], []
    for frame in m.frames:
        m.mark("velocity of frame " + frame.name)
        E, r = frame_pose(frame)
        w, u = _velocity_at(velocities[frame.body], r)
        R_i = frames[frame.body][0]
        local.append(_rotate(E, w) + _rotate(E, u))
        world.append(sp.matvec(R_i, w) + sp.matvec(R_i, u))
    return local, world


def frame_jacobians(m):
    """J_F (local) and diag(R, R) J_F (world-aligned), 6 rows per frame: the world columns of
    point_jacobian_columns at the frame origin, and the same rotated by R_F^Wᵀ = E R_iᵀ."""
    frames = world_frames(m)
    local_rows, world_rows = [], []
    for frame in m.frames:
        m.mark("Jacobian of frame " + frame.name)
        R_i, p_i = frames[frame.body]
        E, r = frame_pose(frame)
        angular, linear = point_jacobian_columns(m, frames, frame.body, _offset_point(p_i, R_i, r))
        R_FW = sp.transpose(_world_rotation(R_i, E))
        local = [sp.matvec(R_FW, a) + sp.matvec(R_FW, b) for a, b in zip(angular, linear)]
        for k in range(6):
            world_rows.append(tuple((a + b)[k] for a, b in zip(angular, linear)))
            local_rows.append(tuple(col[k] for col in local))
    return local_rows, world_rows


def _bias_at(a_i, v_i, r):
    """Body axes, at the point r: the spatial acceleration (ω̇, a_O + ω̇ × r) and the classical one
    (ω̇, that + ω × (v_O + ω × r)) (Featherstone RBDA Eq. 2.38)."""
    dw, du = sp.ang(a_i), sp.lin(a_i)
    if r is not None:
        du = sp.vadd(du, sp.cross(dw, r))
    w, u = _velocity_at(v_i, r)
    return dw, du, sp.vadd(du, sp.cross(w, u))


def frame_bias_accelerations(m):
    """J̇v of each frame: spatial X_i^F a_i (local axes) and classical (ω̇; p̈) in world axes."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    accelerations = body_accelerations(m, velocities, velocity_bias(m))
    spatial, classical = [], []
    for frame in m.frames:
        m.mark("J̇v of frame " + frame.name)
        E, r = frame_pose(frame)
        dw, du, pdd = _bias_at(accelerations[frame.body], velocities[frame.body], r)
        R_i = frames[frame.body][0]
        spatial.append(_rotate(E, dw) + _rotate(E, du))
        classical.append(sp.matvec(R_i, dw) + sp.matvec(R_i, pdd))
    return spatial, classical


def feet_bias_accelerations(m):
    """J̇v of each foot point: its classical acceleration at a = 0, world axes."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    accelerations = body_accelerations(m, velocities, velocity_bias(m))
    result = []
    for foot in m.feet:
        m.mark("J̇v of foot " + foot.name)
        r = sp.vec(foot.offset) if any(foot.offset) else None
        pdd = _bias_at(accelerations[foot.body], velocities[foot.body], r)[2]
        result.append(sp.matvec(frames[foot.body][0], pdd))
    return result
