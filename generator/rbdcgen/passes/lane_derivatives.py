"""forward_dynamics_derivatives with the isomorphic limbs in SIMD lanes (docs/performance.md, "One
SIMD lane per leg"): the method of differentiate.forward_dynamics_derivatives, ∂a = −M⁻¹ ∂(RNEA − τ_e)
at the forward-dynamics result, M⁻¹Sᵀ and M⁻¹Jᵀ, on the lane model. The residual derivatives, the
factor and the forward dynamics are traced unchanged; what differs is how a right-hand side is
solved and where its solution goes: a trunk column (a trunk dof) is one column with the limbs'
rows in lanes (ltdl_solve with the lane sums, as in forward_dynamics_lanes); a limb column (a limb
dof, its torque, a foot force) stands for one column per limb, each solved apart where the limbs
meet (LaneModel.solve_limb_column)."""

from __future__ import annotations

from . import differentiate
from ..graph import expr as ex
from ..views.limb_lanes import lane_column_order
from ..views.limbs import LimbError, isomorphic_limbs
from ..algorithms import forward_dynamics as fd
from ..algorithms import feet_force_derivatives, jacobian
from ..algorithms.crba import body_transform, depth_first_order, mass_matrix


def forward_dynamics_derivatives(m):
    """The outputs of differentiate.forward_dynamics_derivatives for the lane model m (feet=True)."""
    robot, full = m.robot, m.full
    n, root = robot.nv, robot.root_dofs
    dq, dv = differentiate.residual_derivatives(m)
    parents = fd.dof_parents(robot)
    L, inv_diag = fd.ltdl(mass_matrix(m), parents, m.into_dof)

    def limb_columns(b):
        """The full robot's columns of limb column b, one per lane."""
        return [m.scatter(x) for x in m.solve_limb_column(L, inv_diag, parents, b)]

    out = {}
    for name, rows in (("da_dq", dq), ("da_dv", dv)):
        out[name] = [None] * full.nv
        for c in range(n):
            b = [-rows[r][c] for r in range(n)]
            if c < root:
                out[name][c] = m.scatter(fd.ltdl_solve(L, inv_diag, parents, b, m.into_dof))
                continue
            for k, column in enumerate(limb_columns(b)):
                out[name][m.full_index(c, k)] = column
    out["da_dtau"] = [None] * full.n_joints
    for c in range(root, n):                                                       # Sᵀ
        for k, column in enumerate(limb_columns([ex.const(1.0 if r == c else 0.0) for r in range(n)])):
            out["da_dtau"][m.full_index(c, k) - full.root_dofs] = column
    J = jacobian.feet_jacobian(m) if m.feet else []
    out["da_df"] = [None] * (3 * len(m.scene.feet_for(full)))
    for row in range(len(J)):                                                      # Jᵀ
        for k, column in enumerate(limb_columns(list(J[row]))):
            out["da_df"][m.foot_force_index(row, k)] = column
    order = ("da_dq", "da_dv", "da_dtau", "da_df")
    return differentiate.replace_symbols({name: [x for column in out[name] for x in column] for name in order},
                                       m.tree_acceleration, fd.forward_dynamics(m))


def forward_dynamics_derivative_terms(m):
    """differentiate.forward_dynamics_derivative_terms (rhs, L, D_inv: what the looped solve solves)
    traced on the lane model m (feet=True), in the full robot's layout: the residual's derivatives
    and M's factor by the lane recursions, scattered; Jᵀ's columns from the lane feet's rows; the
    placeholder a solved with that factor (forward_dynamics, as the scalar terms), which the terms
    trace anyway (the articulated-body algorithm would add a pass of its own)."""
    full = m.full
    nv = full.nv
    # negated in the lanes, so that a whole lane value reaches its place in rhs (one vector store)
    dq, dv = (m.scatter_matrix([[-x for x in row] for row in rows]) for rows in differentiate.residual_derivatives(m))
    selection = differentiate.selection_columns(full)
    J = m.place_rows(jacobian.feet_jacobian(m), m.foot_places, 3) if m.feet else []
    columns = ([[dq[r][c] for r in range(nv)] for c in range(nv)] + [[dv[r][c] for r in range(nv)] for c in range(nv)]
               + selection + [list(row) for row in J])                           # the order of FORWARD_DYNAMICS_COLUMNS
    columns = [columns[c] for c in column_order(full, len(J))]
    L, inv_diag = fd.ltdl(mass_matrix(m), fd.dof_parents(m.robot), m.into_dof)
    terms = {"rhs": differentiate.right_hand_side_rows(columns, nv),
             "L": fd.packed_factor(m.scatter_matrix(L), fd.dof_parents(full)), "D_inv": m.scatter(inv_diag)}
    return differentiate.replace_symbols(terms, m.tree_acceleration, fd.forward_dynamics(m))


def forward_dynamics_derivative_loop_terms(m):
    """differentiate.forward_dynamics_derivative_terms with looped_rnea (rhs without the RNEA's part,
    L, D_inv, the bodies' transforms X, gravity g, the acceleration a and the feet's axes and
    moments: what the looped solve and the looped RNEA derivatives read) traced on the lane model m
    (feet=True), in the full robot's layout: M's factor, a through it, the transforms and the feet's
    rows by the lane recursions, scattered. The columns keep their plain order (the loop subtracts ∂τ
    from the first 2 nv)."""
    full = m.full
    nv = full.nv
    zero = ex.const(0.0)
    J = m.place_rows(jacobian.feet_jacobian(m), m.foot_places, 3) if m.feet else []
    columns = [[zero] * nv] * (2 * nv) + differentiate.selection_columns(full) + [list(row) for row in J]
    L, inv_diag = fd.ltdl(mass_matrix(m), fd.dof_parents(m.robot), m.into_dof)
    transforms = m.scatter_bodies({i: body_transform(m, i) for i in range(1, m.robot.nb)})
    terms = {"rhs": differentiate.right_hand_side_rows(columns, nv),
             "L": fd.packed_factor(m.scatter_matrix(L), fd.dof_parents(full)), "D_inv": m.scatter(inv_diag),
             "X": tuple(x for body in depth_first_order(full)[1:] for x in transforms[body]),
             "g": m.gravity_in_base(), "a": m.scatter(m.tree_acceleration)}
    if m.feet:
        for name, rows in feet_force_derivatives.axes_and_moments(m).items():  # 3 per reduced dof
            scattered = [m.scatter(rows[c::3]) for c in range(3)]
            terms[name] = tuple(scattered[c][y] for y in range(nv) for c in range(3))
    return differentiate.replace_symbols(terms, m.tree_acceleration, fd.forward_dynamics(m))


def column_order(robot, feet_rows):
    """Where forward_dynamics_derivative_terms keeps its right-hand-side columns (the logical column at
    each place): a quadruped's in lane order (limb_lanes.lane_column_order; the feet's columns with the
    trunk's), so that the terms store whole lane values; any other robot's as they are."""
    dofs = (tuple(range(robot.nv)), tuple(range(robot.nv)),
            tuple(robot.joints[i].v_index for i in range(1, robot.nb)), (-1,) * feet_rows)
    try:
        return lane_column_order(robot, isomorphic_limbs(robot), dofs)
    except LimbError:
        return tuple(range(sum(map(len, dofs))))
