"""Centre of mass, its Jacobian and the centroidal momentum (Orin, Goswami & Lee 2013; the runtime's
runtime/src/centroidal.cpp), world axes, h_G = (k_G; l). The mass counts every body and every rotor
(a point mass at its origin on the carrier λ(i)); masses are constants, so 1/m folds. A_G comes from
the CRBA's composite inertias, Ȧ_G v from the root wrench of the quadratic-velocity pass (Alg. 2)."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .kinematics import body_velocities, world_frames
from .rnea import rnea, velocity_bias


def specs(nv):
    """name → (doc, input names, [(output name, rows, cols, doc)]) of the centroidal functions, for
    their scalar and lane traces (passes/trace.py, passes/lane_functions.py)."""
    return {
        "center_of_mass": (
            "Centre of mass and its velocity, world frame (bodies and rotors).", ("q", "v"),
            [("com", 3, 1, "centre of mass"), ("com_velocity", 3, 1, "its velocity")]),
        "center_of_mass_jacobian": (
            "Centre-of-mass Jacobian J_c, ċ = J_c v, world frame.", ("q",),
            [("J_c", 3, nv, "centre-of-mass Jacobian")]),
        "centroidal_momentum_matrix": (
            "Centroidal momentum matrix A_G (Orin, Goswami & Lee 2013): h_G = A_G v.", ("q",),
            [("A_G", 6, nv, "rows: angular momentum about the CoM, then linear momentum, world axes")]),
        "centroidal_bias": (
            "Centroidal momentum drift Ȧ_G v: the rate of h_G at a = 0.", ("q", "v"),
            [("Adot_v", 6, 1, "(k̇_G; l̇) at a = 0, world axes")]),
    }


def _rotor_masses(m, i):
    """(mass, point in body i's coordinates) of the rotors body i carries (rotor j spins on λ(j))."""
    robot = m.robot
    return [(robot.joints[j].actuator.rotor.mass, robot.joints[j].actuator.rotor.translation)
            for j in robot.children[i] if m.rotor(j) is not None and robot.joints[j].actuator.rotor.mass]


def _subtree_sums(m, own):
    """Per body i, the sum of own(i) (a tuple of expressions) over its subtree ν(i): summed inward,
    each body's sum joining its parent's through into_parent (the sum over the lanes where a lane
    limb meets the trunk, views/limb_lanes.py)."""
    robot = m.robot
    sums = [own(i) for i in range(robot.nb)]
    for i in range(robot.nb - 1, 0, -1):
        j = robot.parent[i]
        sums[j] = tuple(a + b for a, b in zip(sums[j], m.into_parent(i, sums[i])))
    return sums


def subtree_masses_and_moments(m, frames):
    """Per body i, (m_ν(i), s_ν(i) = Σ m_k p_k): the mass and the first moment (world axes) of the
    point masses its subtree carries, each body's m_i p_i + R_i h_i (h_i its first moment in body
    axes) and its rotors' points."""
    def own(i):
        inertia = m.inertia(i)
        R_i, p_i = frames[i]
        mass = inertia.m
        moment = sp.vadd(sp.vscale(mass, p_i), sp.matvec(R_i, inertia.h))
        for rotor_mass, r in _rotor_masses(m, i):
            mass = mass + ex.const(rotor_mass)
            moment = sp.vadd(moment, sp.vscale(ex.const(rotor_mass), sp.vadd(p_i, sp.matvec(R_i, sp.vec(r)))))
        return (mass,) + tuple(moment)
    return [(s[0], s[1:]) for s in _subtree_sums(m, own)]


def center_of_mass(m, frames=None):
    """c = s_ν(0) / m: the first moment of the whole tree over its (constant) mass."""
    frames = frames or world_frames(m)
    m.mark("centre of mass")
    total, moment = subtree_masses_and_moments(m, frames)[0]
    return sp.vscale(ex.const(1.0) / total, moment)


def center_of_mass_velocity(m):
    """ċ = Σ R_i (m_i v_i + ω_i × h_i) / m, rotors as points r: R_i m_r (v_i + ω_i × r)."""
    frames = world_frames(m)
    velocities = body_velocities(m)
    m.mark("centre of mass velocity")

    def own(i):
        inertia = m.inertia(i)
        w, u = sp.ang(velocities[i]), sp.lin(velocities[i])
        mass, momentum = inertia.m, sp.vadd(sp.vscale(inertia.m, u), sp.cross(w, inertia.h))
        for rotor_mass, r in _rotor_masses(m, i):
            mass = mass + ex.const(rotor_mass)
            momentum = sp.vadd(momentum, sp.vscale(ex.const(rotor_mass), sp.vadd(u, sp.cross(w, sp.vec(r)))))
        return (mass,) + tuple(sp.matvec(frames[i][0], momentum))
    total = _subtree_sums(m, own)[0]
    return sp.vscale(ex.const(1.0) / total[0], total[1:])


def center_of_mass_outputs(m):
    """center_of_mass's outputs, for its scalar and its lane trace."""
    return {"com": tuple(center_of_mass(m)), "com_velocity": tuple(center_of_mass_velocity(m))}


def center_of_mass_jacobian(m):
    """J_c (3 × nv) by subtrees: with s_j and m_j the first moment and mass of ν(j)'s point masses,
    column j is a_j × (s_j − m_j p_j)/m (revolute) or a_j m_j/m (prismatic), a_j the world axis; a
    floating base's ω_B columns are R e_c × (c − p_0), its v_B columns R e_c."""
    robot = m.robot
    frames = world_frames(m)
    m.mark("centre of mass Jacobian, subtree moments")
    subtree = subtree_masses_and_moments(m, frames)
    inv = ex.const(1.0) / subtree[0][0]
    cols = [sp.zeros(3) for _ in range(robot.nv)]
    if robot.floating_base:
        R, p0 = frames[0]
        lever = sp.vsub(sp.vscale(inv, subtree[0][1]), p0)
        Rt = sp.transpose(R)
        for c in range(3):
            cols[c] = sp.cross(Rt[c], lever)
            cols[3 + c] = Rt[c]
    for j in range(1, robot.nb):
        m.mark("centre of mass Jacobian", j)
        R_j, p_j = frames[j]
        axis = sp.matvec(R_j, sp.vec(m.axis(j)))
        col = m.joint(j).v_index
        mass, moment = subtree[j]
        if m.joint(j).type == "revolute":
            cols[col] = sp.vscale(inv, sp.cross(axis, sp.vsub(moment, sp.vscale(mass, p_j))))
        else:
            cols[col] = sp.vscale(mass * inv, axis)
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
