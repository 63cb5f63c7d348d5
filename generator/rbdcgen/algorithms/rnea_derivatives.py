"""Analytic first derivatives of the RNEA, ∂τ/∂q and ∂τ/∂v (Carpentier & Mansard, RSS 2018, in the
composite form of Singh, Russell & Wensing, RA-L 2022), traced like every other algorithm so that
folding, CSE and DCE apply. The manifold convention of ∂/∂q is docs/conventions.md's.

Why it is cheap. A perturbation of joint j's coordinate moves the subtree of j rigidly about S_j, so
every world quantity of that subtree changes by S_j × (·) plus a deviation that is the same for all
its bodies; only the deviation survives in τ (the rigid part cancels in S_iᵀ F_i). Summed over a
subtree, the deviations need the composite inertia I^C (the CRBA's), the composite momentum P^C and
the composite inertia rate İ^C = Σ_k (v_k ×* I_k − I_k v_k ×), i.e. B^C x = İ^C x + x ×* P^C. With,
for joint j (λ its parent, everything in joint j's body coordinates),
    u_j = v_j × S_j,   c_j = a_λ × S_j + v_λ × u_j,
    G_j = S_j ×* F_j + I^C_j c_j + B^C_j u_j,   D_j = 2 I^C_j u_j + B^C_j S_j,
the entries are, for i in the subtree of j (i ⪰ j) and for i an ancestor of j (i ≺ j):
    ∂τ_i/∂q_j = S_iᵀ (I^C_i c_j + B^C_i u_j),  ∂τ_i/∂q̇_j = S_iᵀ (2 I^C_i u_j + B^C_i S_j)   (i ⪰ j)
    ∂τ_i/∂q_j = S_iᵀ G_j,                       ∂τ_i/∂q̇_j = S_iᵀ D_j                        (i ≺ j)
The first line is evaluated as the rows ρ^I_i = I^C_i S_i (the CRBA's F_i) and ρ^B_i = B^C_iᵀ S_i
carried to j's frame dotted with the columns; the second carries G_j, D_j inward. Each hop is one
force transform X_λ(i)^iᵀ with the joint's own sparse factors.

A floating base is the 6-dof joint of body 0 with parent the (inertial) world: S₀ = 1 in trunk
coordinates, v_λ = 0, a_λ = the fictitious gravity acceleration. The trunk's acceleration input is
the classical one (docs/conventions.md), a₀ = a − (0, ω × v) + gravity, so a trunk velocity column
also moves a₀: column e gets I^C (v₀ × e − (0, ∂(ω × v)/∂e)) instead of 2 I^C u.
"""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .kinematics import body_velocities
from .rnea import gravity_acceleration


def has_rotors(robot):
    """Rotor bodies (issue 14) are not part of this recursion: derivatives.py then differentiates
    the traced RNEA instead."""
    return any(j.actuator is not None and j.actuator.rotor is not None for j in robot.joints)


def _skew(r):
    return [[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]]


def _product(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(3)) for c in range(3)] for r in range(3)]


def inertia_rate(inertia, v):
    """İ = v ×* I − I v× of a body moving with twist v = (ω, υ), in its own coordinates: a spatial
    inertia of mass 0 with first moment ω × h + m υ and rotational part ω̃Ī − Īω̃ − (υ̃h̃ + h̃υ̃).
    Ī and h of a body are constants, so each entry of the rotational part is built as a linear
    combination of ω and υ with its constant coefficients (most vanish for principal axes)."""
    w, u = sp.ang(v), sp.lin(v)
    basis = [_skew([1.0 if k == n else 0.0 for n in range(3)]) for k in range(3)]
    spin, shift = [], []   # per lane (a limb's constants, views/limb_lanes.py; the same in every lane else)
    for lane in range(ex.LANES):
        ibar = [[ex.constant_lanes(x)[lane] for x in row] for row in inertia.Ibar]
        h_tilde = _skew([ex.constant_lanes(x)[lane] for x in inertia.h])
        spin.append([[[a - b for a, b in zip(x, y)] for x, y in zip(_product(e, ibar),
                                                                    _product(ibar, e))]
                     for e in basis])                                # ẽ_k Ī − Ī ẽ_k
        shift.append([[[-(a + b) for a, b in zip(x, y)] for x, y in zip(_product(e, h_tilde),
                                                                        _product(h_tilde, e))]
                      for e in basis])                               # −(ẽ_k h̃ + h̃ ẽ_k)
    first = sp.vadd(sp.cross(w, inertia.h), sp.vscale(inertia.m, u))
    rows = [[None] * 3 for _ in range(3)]
    for r in range(3):
        for c in range(r, 3):
            entry = ex.const(0.0)
            for coefficients, x in [([s[k][r][c] for s in spin], w[k]) for k in range(3)] + \
                                   [([s[k][r][c] for s in shift], u[k]) for k in range(3)]:
                coefficient = ex.lane_const(coefficients)
                if not coefficient.is_const(0.0):
                    entry = entry + coefficient * x
            rows[r][c] = rows[c][r] = entry
    return sp.Inertia(ex.const(0.0), first, tuple(tuple(row) for row in rows))


def _coriolis(rate, momentum, x):
    """B x = İ x + x ×* P (the composite Coriolis matrix of the subtree applied to a motion x)."""
    return sp.vadd(rate.apply(x), sp.crf(x, momentum))


def _coriolis_transpose(rate, momentum, x):
    """Bᵀ x = İ x − x ×* P (İ is symmetric, P ↦ x ×* P skew)."""
    return sp.vsub(rate.apply(x), sp.crf(x, momentum))


class _Tree:
    """The outward pass (velocities, accelerations, forces, momenta per body, body coordinates) and
    the inward composites (F, I^C, İ^C, P^C) the derivative entries need. A body's composites join
    its parent's through m.into_parent (summed over the lanes where a lane limb meets the trunk,
    views/limb_lanes.py); nothing else of the recursion mixes limbs: a limb's columns and rows reach the
    trunk's rows and columns as lane values, one per limb (LaneModel.scatter_matrix)."""

    def __init__(self, m, base_acceleration, joint_accelerations, with_velocity):
        robot = m.robot
        nb = robot.nb
        self.m = m
        self.with_velocity = with_velocity
        zero6 = sp.zeros(6)
        self.v = body_velocities(m) if with_velocity else [zero6] * nb
        self.v_parent = [zero6] * nb    # v_λ(i) in body i coordinates
        self.a_parent = [zero6] * nb    # a_λ(i) in body i coordinates
        a = [base_acceleration]
        for i in range(1, nb):
            m.mark("derivatives: outward pass, accelerations", i)
            j = robot.parent[i]
            X = m.X_up(i)
            S = m.motion_subspace(i)
            self.a_parent[i] = X.motion(a[j])
            a_i = self.a_parent[i]
            if with_velocity:
                self.v_parent[i] = X.motion(self.v[j])
                a_i = sp.vadd(a_i, sp.crm(self.v[i], sp.vscale(m.vi(i), S)))
            if joint_accelerations is not None:
                a_i = sp.vadd(a_i, sp.vscale(joint_accelerations[i], S))
            a.append(a_i)
        forces, momenta, rates = [], [], []
        for i in range(nb):
            m.mark("derivatives: outward pass, forces", i)
            inertia = m.inertia(i)
            f_i = inertia.apply(a[i])
            if with_velocity:
                p_i = inertia.apply(self.v[i])
                f_i = sp.vadd(f_i, sp.crf(self.v[i], p_i))
                momenta.append(p_i)
                rates.append(inertia_rate(inertia, self.v[i]))
            forces.append(f_i)
        composite = [m.inertia(i) for i in range(nb)]
        for i in range(nb - 1, 0, -1):
            m.mark("derivatives: inward pass, composites", i)
            j = robot.parent[i]
            X = m.X_up(i)
            forces[j] = sp.vadd(forces[j], m.into_parent(i, X.force_T(forces[i])))
            composite[j] = composite[j] + m.into_parent(i, X.congruence(composite[i]))
            if with_velocity:
                momenta[j] = sp.vadd(momenta[j], m.into_parent(i, X.force_T(momenta[i])))
                rates[j] = rates[j] + m.into_parent(i, X.congruence(rates[i]))
        self.F, self.inertia, self.momentum, self.rate = forces, composite, momenta, rates

    def coriolis(self, i, x):
        return _coriolis(self.rate[i], self.momentum[i], x) if self.with_velocity else sp.zeros(6)

    def coriolis_transpose(self, i, x):
        if not self.with_velocity:
            return sp.zeros(6)
        return _coriolis_transpose(self.rate[i], self.momentum[i], x)


def _inward(m, body, vector):
    """[(ancestor, vector in its coordinates)] for the strict ancestors of `body` down to 0: the
    force `vector` carried inward by X_λᵀ one hop at a time."""
    out = []
    while body != 0:
        vector = m.X_up(body).force_T(vector)
        body = m.robot.parent[body]
        out.append((body, vector))
    return out


def rnea_derivatives(m, base_acceleration, joint_accelerations, with_velocity):
    """(∂τ/∂q, ∂τ/∂v) of rnea.rnea(m, base_acceleration, joint_accelerations, with_velocity) as nv×nv
    row lists; base_acceleration is the trunk acceleration built by rnea.base_acceleration (its
    velocity and gravity terms are differentiated here)."""
    robot = m.robot
    nv, nb = robot.nv, robot.nb
    zero = ex.const(0.0)
    dq = [[zero] * nv for _ in range(nv)]
    dv = [[zero] * nv for _ in range(nv)]
    t = _Tree(m, base_acceleration, joint_accelerations, with_velocity)
    col = [None] + [m.joint(i).v_index for i in range(1, nb)]

    # Per joint j: its columns in its own coordinates.
    S = [None] + [m.motion_subspace(i) for i in range(1, nb)]
    u, c = [None] * nb, [None] * nb
    for j in range(1, nb):
        m.mark("derivatives: columns", j)
        u[j] = sp.crm(t.v[j], S[j]) if with_velocity else sp.zeros(6)
        c[j] = sp.crm(t.a_parent[j], S[j])
        if with_velocity:
            c[j] = sp.vadd(c[j], sp.crm(t.v_parent[j], u[j]))

    # Rows of each body i: ρ^I_i, ρ^B_i carried to every ancestor j, dotted with j's columns.
    rows_at = [dict() for _ in range(nb)]   # rows_at[i][j] = (ρ^I_i, ρ^B_i) in body j coordinates
    for i in range(1, nb):
        m.mark("derivatives: rows", i)
        rho = (t.inertia[i].apply(S[i]), t.coriolis_transpose(i, S[i]))
        rows_at[i][i] = rho
        up_I = _inward(m, i, rho[0])
        up_B = _inward(m, i, rho[1])
        for (body, rI), (_, rB) in zip(up_I, up_B):
            rows_at[i][body] = (rI, rB)

    for j in range(1, nb):
        m.mark("derivatives: subtree entries", j)
        two_u = sp.vscale(ex.const(2.0), u[j])
        for i in range(j + 1, nb):
            if j not in rows_at[i]:
                continue
            rI, rB = rows_at[i][j]
            dq[col[i]][col[j]] = sp.dot(rI, c[j]) + sp.dot(rB, u[j])
            dv[col[i]][col[j]] = sp.dot(rI, two_u) + sp.dot(rB, S[j])
        G = sp.vadd(sp.vadd(sp.crf(S[j], t.F[j]), t.inertia[j].apply(c[j])), t.coriolis(j, u[j]))
        D = sp.vadd(t.inertia[j].apply(two_u), t.coriolis(j, S[j]))
        dq[col[j]][col[j]] = sp.dot(S[j], G)
        dv[col[j]][col[j]] = sp.dot(S[j], D)
        m.mark("derivatives: ancestor entries", j)
        for (body, Gb), (_, Db) in zip(_inward(m, j, G), _inward(m, j, D)):
            if body == 0:
                if robot.floating_base:
                    for r in range(6):
                        dq[r][col[j]] = Gb[r]
                        dv[r][col[j]] = Db[r]
            else:
                dq[col[body]][col[j]] = sp.dot(S[body], Gb)
                dv[col[body]][col[j]] = sp.dot(S[body], Db)

    if robot.floating_base:
        _trunk_columns(m, t, rows_at, col, dq, dv)
    return dq, dv


def _trunk_columns(m, t, rows_at, col, dq, dv):
    """The six trunk columns: S₀ = 1 (trunk coordinates), parent the world (v = 0, a = gravity)."""
    m.mark("derivatives: trunk columns")
    robot = m.robot
    a_world = gravity_acceleration(m)
    v0 = t.v[0]
    for k in range(6):
        e = sp.vec([1.0 if r == k else 0.0 for r in range(6)])
        c_k = sp.crm(a_world, e)
        # the classical trunk acceleration: a₀ = a − (0, ω × v): ∂a₀/∂e = −(0, ∂(ω × v)/∂e)
        if t.with_velocity:
            w, v = sp.ang(v0), sp.lin(v0)
            bias = sp.vadd(sp.cross(sp.ang(e), v), sp.cross(w, sp.lin(e)))
            shift = sp.vsub(sp.crm(v0, e), sp.zeros(3) + bias)
        else:
            shift = sp.zeros(6)
        for i in range(1, robot.nb):
            rI, rB = rows_at[i][0]
            dq[col[i]][k] = sp.dot(rI, c_k)
            dv[col[i]][k] = sp.dot(rB, e) + sp.dot(rI, shift)
        Fq = t.inertia[0].apply(c_k)
        Fv = sp.vadd(t.coriolis(0, e), t.inertia[0].apply(shift))
        for r in range(6):
            dq[r][k] = Fq[r]
            dv[r][k] = Fv[r]
