"""Forward dynamics by the articulated-body algorithm (Featherstone, Rigid Body Dynamics Algorithms,
2008, Table 7.1), a second form of forward_dynamics: passes/schedule.py traces it beside CRBA + the
sparse LᵀDL factor and keeps the one with fewer instructions. ABA is O(n) whatever the tree; the
factor is O(n·d²) for depth d, so deep chains (a 100-body arm: d = n) take ABA and branched robots
the factor. For trees without rotors or mimic couplings (`applies`); on the lane model too (a limb's
articulated inertia and bias force join its spine body's through m.into_parent).

In body coordinates, with a₀ = the base's fictitious gravity acceleration (rnea.base_acceleration):
    outward:  c_i = v_i × S_i q̇_i,  I^A_i = I_i,  p^A_i = v_i ×* I_i v_i − f_i^ext
    inward:   U_i = I^A_i S_i,  D_i = S_iᵀU_i + armature_i,  u_i = τ_i − S_iᵀ p^A_i,
              I^a = I^A_i − U_i U_iᵀ/D_i,  p^a = p^A_i + I^a c_i + U_i u_i/D_i,
              I^A_λ += X_iᵀ I^a X_i,  p^A_λ += X_iᵀ p^a          (X_i = X_λ(i)^i)
    outward:  a'_i = X_i a_λ + c_i,  q̈_i = (u_i − U_iᵀ a'_i)/D_i,  a_i = a'_i + S_i q̈_i.
A floating base is body 0 with S₀ = 1: its unactuated wrench I^A_0 a₀ + p^A_0 = 0 gives a₀ by a
dense 6 × 6 LDLᵀ solve, a₀ being the RNEA's trunk acceleration (classical, plus the velocity and
fictitious-gravity terms of rnea.base_acceleration, which are taken off for the output)."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .contact_dynamics import dense_ldlt, ldlt_solve
from .kinematics import body_velocity
from .rnea import base_acceleration, foot_wrenches
from .rnea_derivatives import has_rotors


def applies(robot):
    return not robot.couplings and not has_rotors(robot)


def _unit(k):
    return sp.vec([1.0 if r == k else 0.0 for r in range(6)])


def _apply(rows, x):
    return sp.vec([sp.dot(row, x) for row in rows])


def forward_dynamics_aba(m):
    """a (by v index) with M a = Sᵀτ + τ_e − c − g, as forward_dynamics.forward_dynamics."""
    robot = m.robot
    nb = robot.nb
    velocities = [m.base_velocity()] + [None] * (nb - 1)
    external = foot_wrenches(m) if m.feet else [None] * nb
    S = [None] + [m.motion_subspace(i) for i in range(1, nb)]
    floating = robot.floating_base
    bias_acc, IA, pA = [sp.zeros(6)] * nb, [None] * nb, [None] * nb
    for i in range(0 if floating else 1, nb):  # body by body: a velocity dies with its children's
        m.mark("ABA: outward pass, velocities, velocity products and bias forces", i)
        inertia = m.inertia(i)
        if i > 0:
            velocities[i] = body_velocity(m, i, velocities[robot.parent[i]])
            bias_acc[i] = sp.crm(velocities[i], sp.vscale(m.vi(i), S[i]))
        columns = [inertia.apply(_unit(c)) for c in range(6)]
        IA[i] = sp.symmetric_of(6, lambda r, c: columns[c][r])
        pA[i] = sp.crf(velocities[i], inertia.apply(velocities[i]))
        if external[i] is not None:
            pA[i] = sp.vsub(pA[i], external[i])
    U, inv_D, u = [None] * nb, [None] * nb, [None] * nb
    for i in range(nb - 1, 0, -1):
        m.mark("ABA: inward pass, articulated inertias", i)
        U[i] = _apply(IA[i], S[i])
        D = sp.dot(S[i], U[i])
        if m.armature(i):  # a float, or a lane constant on the lane model where the limbs' differ
            D = D + m.armature(i)
        inv_D[i] = ex.const(1.0) / D
        u[i] = m.tau[i - 1] - sp.dot(S[i], pA[i])
        j = robot.parent[i]
        if j == 0 and not floating:
            continue  # the fixed base takes no load
        scaled = sp.vscale(inv_D[i], U[i])
        constant = all(x.op == "const" for x in S[i])
        k = sp.unit_axis_index([x.value for x in S[i]]) if constant and not m.armature(i) else None
        # Iᵃ S = U − U (Sᵀ U)/D = 0 without armature: for S = ±e_k, Iᵃ's row and column k are zeros,
        # which fold through the congruence below
        Ia = sp.symmetric_of(6, lambda r, c: ex.const(0.0) if k in (r, c) else IA[i][r][c] - U[i][r] * scaled[c])
        pa = sp.vadd(sp.vadd(pA[i], _apply(Ia, bias_acc[i])), sp.vscale(u[i], scaled))
        if k is not None:  # and Sᵀ pᵃ = Sᵀ pᴬ + 0 + u = τ_i
            pa = pa[:k] + (S[i][k] * m.tau[i - 1],) + pa[k + 1:]
        X = m.X_up(i)
        carried = m.into_parent(i, X.congruence6(Ia))
        IA[j] = sp.symmetric_of(6, lambda r, c: IA[j][r][c] + carried[r][c])
        pA[j] = sp.vadd(pA[j], m.into_parent(i, X.force_T(pa)))
    qdd = [None] * robot.nv
    if floating:
        m.mark("ABA: trunk acceleration")
        a0 = sp.vec(ldlt_solve(*dense_ldlt(IA[0]), sp.vneg(pA[0])))
        qdd[0:6] = sp.vsub(a0, base_acceleration(m, sp.zeros(6)))
    else:
        a0 = base_acceleration(m, sp.zeros(6))
    accelerations = [a0] + [None] * (nb - 1)
    for i in range(1, nb):
        m.mark("ABA: outward pass, accelerations", i)
        a_i = sp.vadd(m.X_up(i).motion(accelerations[robot.parent[i]]), bias_acc[i])
        qdd_i = (u[i] - sp.dot(U[i], a_i)) * inv_D[i]
        accelerations[i] = sp.vadd(a_i, sp.vscale(qdd_i, S[i]))
        qdd[m.joint(i).v_index] = qdd_i
    return tuple(qdd)
