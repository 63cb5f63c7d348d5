"""Operational-space quantities of the trunk task (paper 001): the O(nd) recursion of Table 1
(Eqs. 29-41) with measured foot forces, and its closed-chain variant of Table 2 (Eqs. 42-47) with
the big-ground-inertia approximation. The task is body 0 (the trunk) in trunk coordinates with
ẍ_t = (ω̇, classical linear acceleration), so Λ_t ẍ_t + b_t = J̄_tᵀ τ + f_t (Eqs. 28, 40, 48)."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .crba import depth_first_order
from .kinematics import body_velocities, world_frames
from .rnea import foot_wrenches


def output_specs(n_joints):
    """The outputs of the OSC functions (name, rows, cols, doc), scalar and in lanes."""
    return [("Lambda", 6, 6, "operational-space inertia Λ_t of the trunk task"),
            ("JbarT", 6, n_joints, "dynamically consistent J̄_tᵀ (joint columns)"),
            ("b", 6, 1, "operational-space bias force b_t")]


def terms_specs(nb):
    """The outputs of the OSC functions' looped forms' traced part: J̄ᵀ's column terms for the loop
    in place of J̄ᵀ (column_terms)."""
    return [("Lambda", 6, 6, "operational-space inertia Λ_t of the trunk task"),
            ("columns", 12, nb, "column k < nb − 1: the (k + 1)-th body in depth-first order "
             "(crba.depth_first_order), S_i then w_i = Xᵀ U_i D_i in world coordinates; the last: "
             "the trunk's R_0 (row-major, trunk → world) and p_0"),
            ("b", 6, 1, "operational-space bias force b_t")]


def _recursion(m, articulated, beta, velocities, couplings=None):
    """Table 1 inward loop. `articulated[i]` (I_i^A, dense 6×6) and `beta[i]` (β_i^A) are
    initialised by the caller; returns (Λ_t, J̄_tᵀ as 6 × n_joints rows, b_t). With a dict
    `couplings` (the looped form) J̄_tᵀ's columns are not carried: couplings[i] gets body i's
    w_i = −B_λ(i)i in its parent's coordinates, and J̄_tᵀ has no columns."""
    robot = m.robot
    nb = robot.nb
    B = [dict() for _ in range(nb)]        # B[i][k]: torque-force coupling B_ik (Eq. 32)
    for i in range(nb - 1, 0, -1):
        m.mark("inward pass", i)
        j = robot.parent[i]
        X = m.X_up(i)
        S = m.motion_subspace(i)
        Ia = articulated[i]
        U = sp.matvec(Ia, S)                                        # I_i^A Φ_i
        if m.rotor(i) is not None:
            _joint_with_rotor(m, i, articulated, beta, B, velocities, U, couplings)
            continue
        pivot = sp.dot(S, U)
        if m.armature(i):
            pivot = pivot + m.armature(i)                            # reflected inertia
        D = ex.const(1.0) / pivot                                   # D_i (Eq. 35)
        UD = sp.vscale(D, U)

        def propagate(x):
            """L_iᵀ x = x − I^A Φ D Φᵀ x (Eq. 37)."""
            return sp.vsub(x, sp.vscale(sp.dot(S, x), UD))

        zeta = sp.crm(velocities[i], sp.vscale(m.vi(i), S))        # ζ_i (Eq. 29)
        p = sp.vadd(beta[i], sp.matvec(Ia, zeta))
        LIa = sp.symmetric(tuple(sp.vsub(Ia[r], sp.vscale(UD[r], U)) for r in range(6)))
        articulated[j] = sp.mat6_add(articulated[j], m.into_parent(i, X.congruence6(LIa)))
        beta[j] = sp.vadd(beta[j], m.into_parent(i, X.force_T(propagate(p))))
        _couple(B, i, j, X.force_T(UD), couplings,
                lambda column: X.force_T(propagate(column)))
    m.mark("trunk task")
    Lam = articulated[0]
    JbarT_cols = [B[0][k] for k in range(1, nb)] if couplings is None else []
    JbarT = tuple(tuple(col[r] for col in JbarT_cols) for r in range(6))
    v0 = velocities[0]
    trunk_bias = sp.zeros(3) + sp.cross(sp.ang(v0), sp.lin(v0))
    correction = sp.vadd(sp.zeros(3) + m.gravity_in_base(), trunk_bias)
    b = sp.vsub(beta[0], sp.matvec(Lam, correction))                # Eq. 41
    return Lam, JbarT, b


def _couple(B, i, j, w, couplings, carry):
    """Eq. 32's B_ji = −w (w = Xᵀ U_i D_i) and Eq. 37's B_jk = `carry`(B_ik) for the descendants k
    of i; in the looped form only couplings[i] = w."""
    if couplings is not None:
        couplings[i] = w
        return
    B[j][i] = sp.vneg(w)
    for k, column in B[i].items():
        B[j][k] = carry(column)


def _joint_with_rotor(m, i, articulated, beta, B, velocities, U, couplings):
    """One step of the inward loop for a joint whose rotor (runtime/src/rotors.hpp) rides on the
    parent j: the rotor is a leaf body spinning with q̇_i, so it joins the pivot and the parent's
    articulated quantities as in Cheetah-Software's articulated-body algorithm (runtime osc.cpp):
        U_t = Xᵀ I_i^A Φ_i + X_rotᵀ I_rot S_rot,   D_i = 1 / (Φ_iᵀ I_i^A Φ_i + S_rotᵀ I_rot S_rot + armature_i)
        I_j^A += Xᵀ I_i^A X + X_rotᵀ I_rot X_rot − U_t D_i U_tᵀ
        β_j^A += Xᵀ p_i + X_rotᵀ p_rot − U_t D_i (Φ_iᵀ p_i + S_rotᵀ p_rot)
        B_ji = −U_t D_i,   B_jk = Xᵀ B_ik − U_t D_i Φ_iᵀ B_ik
    with p_i = β_i^A + I_i^A ζ_i and p_rot = v_rot ×* I_rot v_rot + I_rot (v_rot × S_rot q̇_i)."""
    j = m.robot.parent[i]
    X, S = m.X_up(i), m.motion_subspace(i)
    X_rot, S_rot, rotor_inertia = m.rotor(i)
    zeta = sp.crm(velocities[i], sp.vscale(m.vi(i), S))
    p = sp.vadd(beta[i], sp.matvec(articulated[i], zeta))
    F_rot = rotor_inertia.apply(S_rot)                              # constant
    U_t = sp.vadd(X.force_T(U), X_rot.force_T(F_rot))
    pivot = sp.dot(S, U) + sp.dot(S_rot, F_rot)
    if m.armature(i):
        pivot = pivot + m.armature(i)
    D = ex.const(1.0) / pivot
    UD = sp.vscale(D, U_t)
    spin = sp.vscale(m.vi(i), S_rot)
    v_rot = sp.vadd(X_rot.motion(velocities[j]), spin)
    p_rot = sp.vadd(sp.crf(v_rot, rotor_inertia.apply(v_rot)), rotor_inertia.apply(sp.crm(v_rot, spin)))
    carried = sp.symmetric(tuple(sp.vsub(row, sp.vscale(UD[r], U_t))
                                 for r, row in enumerate(sp.mat6_add(X.congruence6(articulated[i]),
                                                                     rotor_inertia.congruence(X_rot).dense()))))
    articulated[j] = sp.mat6_add(articulated[j], carried)
    along = sp.dot(S, p) + sp.dot(S_rot, p_rot)
    beta[j] = sp.vadd(beta[j], sp.vsub(sp.vadd(X.force_T(p), X_rot.force_T(p_rot)), sp.vscale(along, UD)))
    _couple(B, i, j, UD, couplings, lambda column: sp.vsub(X.force_T(column), sp.vscale(sp.dot(S, column), UD)))


def _outward(m):
    """Table 1 outward loop: v_i and the initial I_i^A = I_i, β_i^A = v_i ×* I_i v_i."""
    velocities = body_velocities(m)
    articulated, beta = [], []
    for i in range(m.robot.nb):
        m.mark("outward pass, inertias and bias forces", i)
        inertia = m.inertia(i)
        articulated.append(inertia.dense())
        beta.append(sp.crf(velocities[i], inertia.apply(velocities[i])))
    return velocities, articulated, beta


def _inward(m, articulated, beta, velocities, frames, looped):
    """Table 1's inward loop: (Λ_t, J̄_tᵀ, b_t), or `looped`, (Λ_t, column_terms, b_t)."""
    if not looped:
        return _recursion(m, articulated, beta, velocities)
    couplings = {}
    Lam, _, b = _recursion(m, articulated, beta, velocities, couplings)
    return Lam, column_terms(m, couplings, frames), b


def column_terms(m, couplings, frames):
    """What osc_columns_loop (rbdc_gen/osc.hpp, passes/looped_osc.py) forms J̄_tᵀ from, in world
    coordinates (the bodies' world `frames`, which the recursion's foot terms need anyway): for each
    body i ≥ 1 in depth_first_order, S_i and w_i (`couplings`, in the parent's coordinates), 12 values;
    then the trunk's frame, R_0 row-major and p_0, for the columns' way back to trunk coordinates.
    There Eq. 37 carries a column by B_λ(i)k = Xᵀ B_ik − (S_iᵀ B_ik) w_i without any transform:
    S_iᵀ B_ik is the same number in every coordinates, so the loop only subtracts (S_i·c) w_i from
    each descendant column c, and J̄_tᵀ's column k is −w_k carried to the trunk."""
    values = []
    for i in depth_first_order(m.robot)[1:]:
        m.mark("J̄ᵀ column terms", i)
        R, p = frames[i]
        S = m.motion_subspace(i)
        w = sp.matvec(R, sp.ang(S))
        values += w + sp.vadd(sp.matvec(R, sp.lin(S)), sp.cross(p, w))
        R, p = frames[m.robot.parent[i]]
        f = sp.matvec(R, sp.lin(couplings[i]))
        values += sp.vadd(sp.matvec(R, sp.ang(couplings[i])), sp.cross(p, f)) + f
    R, p = frames[0]
    return tuple(values) + tuple(e for row in R for e in row) + tuple(p)


def osc_open_chain(m, looped=False):
    """Table 1 with the measured foot forces f (world frame): β_i^A −= f_i^e. `looped`: J̄_tᵀ's
    column terms in its place (column_terms)."""
    velocities, articulated, beta = _outward(m)
    frames = world_frames(m)
    for i, wrench in enumerate(foot_wrenches(m, frames)):
        if wrench is not None:
            beta[i] = sp.vsub(beta[i], wrench)
    return _inward(m, articulated, beta, velocities, frames, looped)


def osc_closed_chain(m, looped=False):
    """Table 2 (`looped` as for osc_open_chain): each foot in contact hangs a ground inertia I_c on a spherical joint. With Φ_c the
    angular free modes, L_cᵀ I_c = diag(0, M 1), so Eqs. 46-47 add a point mass M (ground_mass)
    at the foot to I_i^A and Xᵀ (0, M g_c) to β_i^A (g_c: gravity in body coordinates)."""
    velocities, articulated, beta = _outward(m)
    frames = world_frames(m)
    M = m.ground_mass
    for foot in m.contacts:
        m.mark("contact of foot " + foot.name)
        i = foot.body
        r = sp.vec(foot.offset)
        rr = sp.dot(r, r)
        point = sp.Inertia(M, sp.vscale(M, r),
                           sp.symmetric(tuple(tuple(M * ((rr if a == b else 0.0) - r[a] * r[b])
                                                    for b in range(3)) for a in range(3))))
        articulated[i] = sp.mat6_add(articulated[i], point.dense())            # Eq. 46
        g_c = sp.mat_tmatvec(frames[i][0], m.gravity)
        force = sp.vscale(M, g_c)
        beta[i] = sp.vadd(beta[i], sp.cross(r, force) + force)                  # Eq. 47
    return _inward(m, articulated, beta, velocities, frames, looped)
