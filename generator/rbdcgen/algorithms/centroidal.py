"""Centre of mass, its Jacobian and the centroidal momentum (Orin, Goswami & Lee 2013; the runtime's
runtime/src/centroidal.cpp), world axes, h_G = (k_G; l). The mass counts every body and every rotor
(a point mass at its origin on the carrier λ(i)); masses are constants, so 1/m folds. A_G comes from
the CRBA's composite inertias, Ȧ_G v from the root wrench of the quadratic-velocity pass (Alg. 2)."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .kinematics import body_velocities, world_frames
from .rnea import rnea, velocity_bias


def point_masses(m):
    """(mass, carrier body, point in carrier coordinates) of every body's COM and every rotor."""
    robot = m.robot
    masses = []
    for i in range(robot.nb):
        body = robot.bodies[i]
        masses.append((body.mass, i, body.com))
        rotor = m.rotor(i) if i > 0 else None
        if rotor is not None:
            masses.append((robot.joints[i].actuator.rotor.mass, robot.parent[i],
                           robot.joints[i].actuator.rotor.translation))
    return [p for p in masses if p[0] != 0]


def _weighted_sum(vectors_and_masses):
    total = sp.zeros(3)
    for mass, x in vectors_and_masses:
        total = sp.vadd(total, sp.vscale(ex.const(mass), x))
    return total


def center_of_mass(m, frames=None):
    """c = Σ m_k (p_i + R_i r_k) / m."""
    frames = frames or world_frames(m)
    masses = point_masses(m)
    m.mark("centre of mass")
    total = sum(p[0] for p in masses)
    s = _weighted_sum([(mass, sp.vadd(frames[b][1], sp.matvec(frames[b][0], sp.vec(r)))) for mass, b, r in masses])
    return sp.vscale(ex.const(1.0 / total), s)


def center_of_mass_velocity(m):
    """ċ = Σ m_k R_i (v_i + ω_i × r_k) / m."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    masses = point_masses(m)
    m.mark("centre of mass velocity")
    total = sum(p[0] for p in masses)
    s = _weighted_sum([(mass, sp.matvec(frames[b][0], sp.vadd(sp.lin(velocities[b]),
                                                              sp.cross(sp.ang(velocities[b]), sp.vec(r)))))
                       for mass, b, r in masses])
    return sp.vscale(ex.const(1.0 / total), s)


def center_of_mass_jacobian(m):
    """J_c (3 × nv) by subtrees: with s_j = Σ m_k p_k and m_j = Σ m_k over the point masses carried by
    ν(j), column j is a_j × (s_j − m_j p_j)/m (revolute) or a_j m_j/m (prismatic), a_j the world
    axis; a floating base's ω_B columns are R e_c × (c − p_0), its v_B columns R e_c."""
    robot = m.robot
    frames = world_frames(m)
    masses = point_masses(m)
    total = sum(p[0] for p in masses)
    inv = ex.const(1.0 / total)
    sub_mass = [0.0] * robot.nb
    sub_moment = [sp.zeros(3) for _ in range(robot.nb)]
    m.mark("centre of mass Jacobian, subtree moments")
    for mass, b, r in masses:
        sub_mass[b] += mass
        point = sp.vadd(frames[b][1], sp.matvec(frames[b][0], sp.vec(r)))
        sub_moment[b] = sp.vadd(sub_moment[b], sp.vscale(ex.const(mass), point))
    for i in range(robot.nb - 1, 0, -1):
        j = robot.parent[i]
        sub_mass[j] += sub_mass[i]
        sub_moment[j] = sp.vadd(sub_moment[j], sub_moment[i])
    cols = [sp.zeros(3) for _ in range(robot.nv)]
    if robot.floating_base:
        R, p0 = frames[0]
        lever = sp.vsub(sp.vscale(inv, sub_moment[0]), p0)
        Rt = sp.transpose(R)
        for c in range(3):
            cols[c] = sp.cross(Rt[c], lever)
            cols[3 + c] = Rt[c]
    for j in range(1, robot.nb):
        m.mark("centre of mass Jacobian", j)
        R_j, p_j = frames[j]
        axis = sp.matvec(R_j, sp.vec(m.axis(j)))
        col = m.joint(j).v_index
        if m.joint(j).type == "revolute":
            moment = sp.vsub(sub_moment[j], sp.vscale(ex.const(sub_mass[j]), p_j))
            cols[col] = sp.vscale(inv, sp.cross(axis, moment))
        else:
            cols[col] = sp.vscale(ex.const(sub_mass[j] / total), axis)
    return [tuple(col[r] for col in cols) for r in range(3)]


def _to_com(frames, body, c, wrench):
    """X*_i^G f: a wrench at body i's origin in its axes → at the CoM c in world axes."""
    R_i, p_i = frames[body]
    n, f = sp.matvec(R_i, sp.ang(wrench)), sp.matvec(R_i, sp.lin(wrench))
    return sp.vadd(n, sp.cross(sp.vsub(p_i, c), f)) + f


def composite_inertias(m):
    """I_ci of Alg. 5 (Eq. 26) with the rotors riding on their carriers, body coordinates."""
    robot = m.robot
    composite = [m.inertia(i) for i in range(robot.nb)]
    for i in range(1, robot.nb):
        if m.rotor(i) is not None:
            X_rot, _, rotor_inertia = m.rotor(i)
            composite[robot.parent[i]] = composite[robot.parent[i]] + rotor_inertia.congruence(X_rot)
    for i in range(robot.nb - 1, 0, -1):
        m.mark("inward pass, composite inertias", i)
        j = robot.parent[i]
        composite[j] = composite[j] + m.into_parent(i, m.X_up(i).congruence(composite[i]))
    return composite


def centroidal_momentum_matrix(m):
    """A_G (6 × nv), rows (k_G; l): column block of joint j = X*_j^G I_cj S_j (Orin et al. Eq. 25),
    a floating base's X*_0^G I_c0, plus X*_λ(j)^G X_rotᵀ I_rot S_rot for rotor j's spin."""
    robot = m.robot
    frames = world_frames(m)
    c = center_of_mass(m, frames)
    composite = composite_inertias(m)
    cols = [None] * robot.nv
    if robot.floating_base:
        for k in range(6):
            unit = sp.vec([1.0 if r == k else 0.0 for r in range(6)])
            cols[k] = _to_com(frames, 0, c, composite[0].apply(unit))
    for j in range(1, robot.nb):
        m.mark("centroidal momentum matrix", j)
        h = _to_com(frames, j, c, composite[j].apply(m.motion_subspace(j)))
        if m.rotor(j) is not None:
            X_rot, S_rot, rotor_inertia = m.rotor(j)
            spin = X_rot.force_T(rotor_inertia.apply(S_rot))
            h = sp.vadd(h, _to_com(frames, robot.parent[j], c, spin))
        cols[m.joint(j).v_index] = h
    return [tuple(col[r] for col in cols) for r in range(6)]


def centroidal_bias(m):
    """Ȧ_G v = X*_0^G f_0 with f_0 the root wrench of the quadratic-velocity pass (Orin et al. Eq.
    26; the CoM's own motion drops out, ċ × m ċ = 0)."""
    frames = world_frames(m)
    c = center_of_mass(m, frames)
    root = rnea(m, velocity_bias(m), None, True, root_wrench=True)[:6]
    m.mark("centroidal bias")
    return _to_com(frames, 0, c, root)
