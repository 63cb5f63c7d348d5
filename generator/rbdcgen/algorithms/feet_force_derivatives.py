"""∂(Jᵀf)/∂q at fixed world foot forces, analytically from the world feet Jacobian (docs/conventions.md:
∂/∂q on the manifold, tangent ordered like v).

τ_e,y = Σ_k J_ky · f_k with J_ky foot k's world velocity per unit q̇_y. Perturbing dof x moves the
subtree of x rigidly about its world axis ω_x (the trunk's δθ_c turns the whole robot about R e_c,
δp moves it without turning: ω = 0), so for dofs x ⪯ y on foot k's path, ∂J_ky/∂q_x = ω_x × J_ky,
and for x ≺ y the foot itself moves by J_kx, ∂J_kx/∂q_y = ω_x × J_ky. Both give the same entry:
    ∂τ_e,y/∂q_x = ∂τ_e,x/∂q_y = Σ_k ω_x · (J_ky × f_k)    (x ≺ y; symmetric)
    ∂τ_e,y/∂q_y = Σ_k ω_y · (J_ky × f_k),   trunk block: ∂τ_e,r/∂q_c = Σ_k ω_c · (J_kr × f_k)
where the trunk's six dofs are one body (r, c both trunk dofs).

An entry depends on the pair (x, y) only through ω_x and χ_y = Σ_k J_ky × f_k (J_ky is zero off foot
k's path), so the looped form (passes/looped_feet_forces.py) traces those two per dof, O(n), and a
loop over the dof tree's ancestor pairs forms the O(n·depth) entries."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .jacobian import feet_jacobian
from .kinematics import world_frames


def dof_axes(m, frames):
    """The world angular axis of each dof (None for a translation: δp, prismatic joints)."""
    robot = m.robot
    axes = [None] * robot.nv
    if robot.floating_base:
        Rt = sp.transpose(frames[0][0])
        for c in range(3):
            axes[c] = Rt[c]
    for j in range(1, robot.nb):
        if m.joint(j).type == "revolute":
            axes[m.joint(j).v_index] = sp.matvec(frames[j][0], sp.vec(m.axis(j)))
    return axes


def feet_force_term_derivatives(m):
    """nv × nv rows of ∂(Jᵀf)/∂q."""
    robot = m.robot
    nv = robot.nv
    zero = ex.const(0.0)
    out = [[zero] * nv for _ in range(nv)]
    J = feet_jacobian(m)
    axes = dof_axes(m, world_frames(m))
    trunk = list(range(robot.root_dofs))
    for k, foot in enumerate(m.feet):
        m.mark("derivatives: force of foot " + foot.name)
        f = m.foot_force(k)
        path = [m.joint(j).v_index for j in sorted(robot.support[foot.body])]   # root → foot
        chi = {y: sp.cross(tuple(J[3 * k + r][y] for r in range(3)), f) for y in trunk + path}

        def add(row, col, axis, y, k=k):
            if axis is not None:  # a lane foot's term summed over its lanes between two spine dofs
                out[row][col] = out[row][col] + m.into_spine(k, row, col, sp.dot(axis, chi[y]))

        for r in trunk:
            for c in trunk:
                add(r, c, axes[c], r)
        for n, y in enumerate(path):
            add(y, y, axes[y], y)
            for x in trunk + path[:n]:
                add(y, x, axes[x], y)
                add(x, y, axes[x], y)
    return out


def axes_and_moments(m):
    """What the looped form reads: per dof its world axis ω (zero for a translation) and
    χ = Σ_k J_k × f_k, nv × 3 each, row-major."""
    zero = ex.const(0.0)
    J = feet_jacobian(m)
    axes = dof_axes(m, world_frames(m))
    moments = [sp.zeros(3)] * m.robot.nv
    for k in range(len(m.feet)):
        m.mark("derivatives: moments of the force of foot " + m.feet[k].name)
        f = m.foot_force(k)
        for y in range(m.robot.nv):
            column = tuple(J[3 * k + r][y] for r in range(3))
            if not all(x.is_const(0.0) for x in column):
                moments[y] = sp.vadd(moments[y], m.into_spine(k, y, y, sp.cross(column, f)))
    return {"feet_axes": tuple(x for axis in axes for x in (axis if axis is not None else (zero,) * 3)),
            "feet_moments": tuple(x for moment in moments for x in moment)}


def rows_with_feet(robot, feet):
    """The dofs below the trunk with one of `feet` below them (χ ≠ 0), in order."""
    below = sorted({robot.joints[j].v_index for foot in feet for j in robot.support[foot.body]})
    return tuple(y for y in below if y >= robot.root_dofs)
