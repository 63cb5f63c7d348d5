"""Derivatives of the dynamics from the traced graph: forward-mode tangents of the DAG.

`propagate` pushes tangents through a DAG in topological order, one sparse {direction: Expr} map
per node, with the folding constructors of expr.py: a node that does not depend on a direction
has no entry for it, so the zeros of the tree's sparsity never appear (a joint's angle only
reaches its subtree outward and its ancestors inward), and CSE merges the tangent work that
directions share with the primal (e.g. d sin q = cos q, which is already a node). The manifold
seeding of ∂/∂q lives in manifold.py.

Quantities (docs/conventions.md "Derivatives", docs/generator.md says why each takes its method):
    inverse_dynamics_derivatives   ∂τ/∂q, ∂τ/∂v of τ = RNEA(q, v, a)          tangents
    bias_derivatives               ∂(c + g)/∂q, ∂(c + g)/∂v                  tangents
    gravity_derivatives            ∂g/∂q                                     tangents
    feet_velocity_derivatives      ∂ṗ_feet/∂q                                tangents
    feet_force_term_derivatives    ∂(Jᵀf)/∂q at fixed world forces           tangents
    forward_dynamics_derivatives   ∂a/∂q, ∂a/∂v = −M⁻¹ ∂(RNEA − τ_e)/∂(q, v) at the forward-dynamics
                                   result, ∂a/∂τ = M⁻¹Sᵀ, ∂a/∂f = M⁻¹Jᵀ, all by multi-right-hand-side
                                   solves with the LᵀDL factor forward_dynamics already traces
    contact_dynamics_derivatives   ∂(a, λ)/∂(q, v, τ) of contact_dynamics: the KKT rows differentiated
                                   at held (a, λ) (the RNEA − Jᵀλ residual as above, tangents of the
                                   contact points' J a + J̇v), solved through the Delassus factor
"""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from ..algorithms import forward_dynamics as fd
from ..algorithms import contact_dynamics as cd
from ..algorithms import aba, crba, feet_force_derivatives, feet_motion_derivatives, jacobian, rnea
from ..algorithms.rnea_derivatives import has_rotors, rnea_derivatives
from ..graph.manifold import configuration_seeds, q_direction, v_direction, velocity_seeds
from ..views.coupled import tree_view
from .looped_inverse import tau_by_inverse

# The primal function each derivative is compared with in `rbdc flops` (the targets are
# ratios to one primal call). bias_derivatives differentiates inverse dynamics at a = 0.
PRIMAL = {
    "inverse_dynamics_derivatives": "inverse_dynamics",
    "bias_derivatives": "inverse_dynamics",
    "gravity_derivatives": "gravity_terms",
    "forward_dynamics_derivatives": "forward_dynamics",
    "feet_velocity_derivatives": "feet_velocities",
    "feet_force_term_derivatives": "feet_force_terms",
    "contact_dynamics_derivatives": "contact_dynamics",
}


def _merge(x, y, combine, only_x, only_y):
    """Tangent map of a binary node from its operands' maps."""
    out = {}
    for k, tx in x.items():
        ty = y.get(k)
        out[k] = only_x(tx) if ty is None else combine(tx, ty)
    for k, ty in y.items():
        if k not in x:
            out[k] = only_y(ty)
    return {k: t for k, t in out.items() if not t.is_const(0.0)}


def propagate(outputs, seeds):
    """Forward mode over the DAG reaching `outputs`: {direction: tangent Expr} of each output.

    `seeds` maps a node id to its tangents; a seeded node takes them as given (symbols, and the
    intermediate nodes whose tangent is known in closed form); every other leaf has none."""
    tangents = {}
    reciprocal = {}   # div: 1/b once per denominator, shared by all directions

    def inverse(b):
        if b.id not in reciprocal:
            reciprocal[b.id] = ex.const(1.0) / b
        return reciprocal[b.id]

    for node in ex.reachable(outputs):
        if node.id in seeds:
            tangents[node.id] = seeds[node.id]
            continue
        if node.op in ("const", "sym"):
            tangents[node.id] = {}
            continue
        a = node.args
        t = [tangents[x.id] for x in a]
        if not any(t):
            tangents[node.id] = {}
            continue
        op = node.op
        if op == "neg":
            out = {k: -d for k, d in t[0].items()}
        elif op == "add":
            out = _merge(t[0], t[1], lambda x, y: x + y, lambda x: x, lambda y: y)
        elif op == "sub":
            out = _merge(t[0], t[1], lambda x, y: x - y, lambda x: x, lambda y: -y)
        elif op == "mul":
            out = _merge(t[0], t[1], lambda x, y: x * a[1] + a[0] * y,
                         lambda x: x * a[1], lambda y: a[0] * y)
        elif op == "div":
            # d(a/b) = (da − (a/b) db)/b; with a = 1 (pivots) that is −(1/b)² db.
            r = inverse(a[1])
            if a[0].is_const(1.0):
                square = node * node
                out = {k: -(square * d) for k, d in t[1].items()}
            else:
                ratio = node * r
                out = _merge(t[0], t[1], lambda x, y: x * r - ratio * y,
                             lambda x: x * r, lambda y: -(ratio * y))
        elif op == "sin":
            out = {k: ex.cos(a[0]) * d for k, d in t[0].items()}
        elif op == "cos":
            out = {k: -(ex.sin(a[0]) * d) for k, d in t[0].items()}
        elif op == "sqrt":
            half = ex.const(0.5) / node
            out = {k: half * d for k, d in t[0].items()}
        else:
            raise AssertionError("rbdcgen.derivatives: no tangent rule for '%s'" % op)
        tangents[node.id] = {k: d for k, d in out.items() if not d.is_const(0.0)}
    return [tangents[node.id] for node in outputs]


def jacobian_columns(outputs, seeds, directions):
    """Column-major entries of ∂outputs/∂directions (len(outputs) × len(directions))."""
    zero = ex.const(0.0)
    maps = propagate(list(outputs), seeds)
    return tuple(t.get(d, zero) for d in directions for t in maps)


def _q_dirs(m):
    return [q_direction(k) for k in range(m.robot.nv)]


def _v_dirs(m):
    return [v_direction(k) for k in range(m.robot.nv)]


def _state_seeds(m, with_velocity=True):
    seeds = configuration_seeds(m)
    if with_velocity:
        for node_id, tangent in velocity_seeds(m).items():
            seeds.setdefault(node_id, {}).update(tangent)
    return seeds


def q_and_v(m, outputs, q_name, v_name):
    seeds = _state_seeds(m)
    return {q_name: jacobian_columns(outputs, seeds, _q_dirs(m)),
            v_name: jacobian_columns(outputs, seeds, _v_dirs(m))}


def _trunk_acceleration(m):
    return m.a[0:6] if m.robot.floating_base else sp.zeros(6)


def column_major(rows):
    n = len(rows)
    return tuple(rows[r][c] for c in range(len(rows[0]) if rows else 0) for r in range(n))


def _rnea_q_and_v(m, base_acceleration, joint_accelerations, with_velocity, names):
    """∂/∂q and ∂/∂v of rnea.rnea(m, ...) (no external forces): the analytic recursion, or the
    tangents of the traced RNEA for a robot with rotors (which the recursion does not model)."""
    if has_rotors(m.robot):
        tau = rnea.rnea(m, base_acceleration, joint_accelerations, with_velocity)
        return q_and_v(m, tau, *names)
    dq, dv = rnea_derivatives(m, base_acceleration, joint_accelerations, with_velocity)
    return {name: column_major(m.scatter_matrix(rows)) for name, rows in zip(names, (dq, dv))}


def inverse_dynamics_derivatives(m):
    return _rnea_q_and_v(m, rnea.base_acceleration(m, _trunk_acceleration(m)),
                         rnea.joint_accelerations(m), True, ("dtau_dq", "dtau_dv"))


def bias_derivatives(m):
    return _rnea_q_and_v(m, rnea.base_acceleration(m, sp.zeros(6)), None, True,   # c + g
                         ("dbias_dq", "dbias_dv"))


def gravity_derivatives(m):
    out = _rnea_q_and_v(m, rnea.gravity_acceleration(m), None, False, ("dg_dq", "dg_dv"))
    return {"dg_dq": out["dg_dq"]}


def feet_velocity_derivatives(m):
    return {"dpdot_dq": column_major(feet_motion_derivatives.feet_velocity_derivatives(m))}


def feet_force_term_derivatives(m):
    return {"dtau_e_dq": column_major(feet_force_derivatives.feet_force_term_derivatives(m))}


def _solve_columns(m, columns):
    """M⁻¹ applied to each column (a list of nv-vectors) with the factor of forward_dynamics:
    the same LᵀDL nodes (hash-consing makes the second trace of M and its factor free)."""
    parents = fd.dof_parents(m.robot)
    L, inv_diag = fd.ltdl(crba.mass_matrix(m), parents)
    return [fd.ltdl_solve(L, inv_diag, parents, col) for col in columns]


_BUILD = {"neg": ex.neg, "add": ex.add, "sub": ex.sub, "mul": ex.mul, "div": ex.div,
          "sin": ex.sin, "cos": ex.cos, "sqrt": ex.sqrt, "lane_sum": ex.lane_sum}


def substitute(outputs, replacement):
    """`outputs` rebuilt (with folding) with the nodes of `replacement` ({node id: Expr}) replaced."""
    new = {}
    for node in ex.reachable(outputs):
        if node.id in replacement:
            new[node.id] = replacement[node.id]
        elif not node.args:
            new[node.id] = node
        else:
            args = [new[a.id] for a in node.args]
            if all(x is y for x, y in zip(args, node.args)):
                new[node.id] = node
            elif node.op == "lane_get":
                new[node.id] = ex.lane_get(args[0], node.value)
            elif node.op == "lane_rotate":
                new[node.id] = ex.lane_rotate(args[0], node.value)
            else:
                new[node.id] = _BUILD[node.op](*args)
    return [new[node.id] for node in outputs]


def residual_derivatives(m):
    """∂/∂q and ∂/∂v (nv × nv rows) of the forward-dynamics residual RNEA(q, v, a) − τ_e(q, f) at
    the placeholder symbols a: the analytic recursion for the RNEA, tangents for τ_e (its world
    forces do not turn with the bodies, so the recursion's rigid-motion argument does not cover
    them); all tangents for a robot with rotors."""
    nv = m.robot.nv
    base = rnea.base_acceleration(m, _trunk_acceleration(m))
    if has_rotors(m.robot):
        external = rnea.foot_wrenches(m) if m.feet else None
        residual = rnea.rnea(m, base, rnea.joint_accelerations(m), True, external)
        maps = propagate(list(residual), _state_seeds(m))
        zero = ex.const(0.0)
        return tuple([[maps[r].get(direction(c), zero) for c in range(nv)] for r in range(nv)]
                     for direction in (q_direction, v_direction))
    dq, dv = rnea_derivatives(m, base, rnea.joint_accelerations(m), True)
    if m.feet:
        external = feet_force_derivatives.feet_force_term_derivatives(m)
        dq = [[x - y for x, y in zip(row, ext)] for row, ext in zip(dq, external)]
    return dq, dv


def _mirror_joint_block(robot, dtau):
    """M⁻¹Sᵀ (column-major nv × n_joints) holds the joint block of the symmetric M⁻¹: the entries
    above its diagonal are taken from below it, so DCE drops half of their solve's last pass."""
    nv = robot.nv
    dofs = [robot.joints[i].v_index for i in range(1, robot.nb)]
    for a, row_a in enumerate(dofs):
        for b in range(a):
            dtau[a * nv + dofs[b]] = dtau[b * nv + row_a]


# Columns per row of the looped forms' right-hand sides, a multiple of this: a row is then whole
# 64-byte lines and whole AVX-512 vectors, so the loops (rbdc_gen/solve.hpp) have no remainder and no
# access splits a cache line (g++ solved humanoid32's 123 columns in half the time at 128).
ROW_ALIGNMENT = 8


# The Delassus factor's halves and the proximal steps' sum (3·nc columns, contact_terms) are padded
# to a multiple of this only: the Mini Cheetah's 12 columns are then three AVX runs of four where 16
# were two AVX-512 runs of eight, a quarter fewer multiply-adds (rbdc_gen::ColumnRun takes half runs).
STEP_SUM_ALIGNMENT = 4


def padded(columns, alignment=ROW_ALIGNMENT):
    """The row length of `columns` right-hand sides: zero columns up to a multiple of `alignment`."""
    return -(-columns // alignment) * alignment


def step_sum_columns(contact_rows):
    """The row length of the Delassus factor's halves and of the proximal steps' sum."""
    return padded(contact_rows, STEP_SUM_ALIGNMENT)


def right_hand_side_rows(columns, rows, width=None):
    """The first `rows` entries of each column, row-major, each row padded with zeros to `width`
    (default: padded)."""
    zero = ex.const(0.0)
    pad = (width or padded(len(columns))) - len(columns)
    return [x for r in range(rows) for x in [col[r] for col in columns] + [zero] * pad]


# The right-hand sides of forward_dynamics_derivatives, in their output order.
FORWARD_DYNAMICS_COLUMNS = ("da_dq", "da_dv", "da_dtau", "da_df")


def _forward_dynamics_columns(m, looped_rnea=False):
    """The right-hand sides whose M⁻¹-images are ∂a: −∂(RNEA − τ_e)/∂(q, v) at the placeholder a,
    Sᵀ and Jᵀ, as {output name: list of nv-columns}. With `looped_rnea` the ∂q and ∂v columns are
    zero: the looped RNEA derivatives subtract the RNEA's part (passes/looped_rnea_derivatives.py),
    and a loop adds ∂τ_e/∂q (looped_feet_forces.py)."""
    robot = m.robot
    nv = robot.nv
    if looped_rnea:
        zero = ex.const(0.0)
        columns = {"da_dq": [[zero] * nv for _ in range(nv)], "da_dv": [[zero] * nv for _ in range(nv)]}
    else:
        dq, dv = residual_derivatives(m)
        columns = {"da_dq": [[-dq[r][c] for r in range(nv)] for c in range(nv)],
                   "da_dv": [[-dv[r][c] for r in range(nv)] for c in range(nv)]}
    columns["da_dtau"] = selection_columns(robot)
    J = jacobian.feet_jacobian(m) if m.feet else []
    columns["da_df"] = [[J[row][c] for c in range(nv)] for row in range(len(J))]  # Jᵀ
    return columns


def selection_columns(robot, sign=1.0):
    """Sᵀ's columns (sign·Sᵀ), one nv-column per joint."""
    return [[ex.const(sign if r == robot.joints[i].v_index else 0.0) for r in range(robot.nv)]
            for i in range(1, robot.nb)]


def forward_dynamics_derivatives(m):
    """∂a = −M⁻¹ ∂(RNEA(q, v, a) − τ_e(q, f)) at a = forward_dynamics(q, v, τ, f). The residual is
    traced with placeholder symbols for a, differentiated with a held fixed, and only then are the
    placeholders replaced by the forward-dynamics result: no differentiation through the
    factorisation."""
    columns = _forward_dynamics_columns(m)
    flat = {name: [x for col in _solve_columns(m, cols) for x in col]
            for name, cols in columns.items()}
    _mirror_joint_block(m.robot, flat["da_dtau"])
    return replace_symbols({name: flat[name] for name in FORWARD_DYNAMICS_COLUMNS}, m.a,
                           fd.forward_dynamics(m))


def forward_dynamics_derivative_terms(m, looped_rnea=False, looped_factor=False, low_rank=False):
    """What forward_dynamics_derivatives solves, unsolved (passes/looped_solve.py solves it in a
    loop): `rhs`, the right-hand sides side by side, row-major (nv × columns, in the order of
    FORWARD_DYNAMICS_COLUMNS, each row zero-padded to `padded` columns; without Sᵀ where ∂a/∂τ is
    M⁻¹'s rows, passes/looped_inverse.py); `L`, the factor's entries
    at each dof's tree ancestors (dof by dof, nearest ancestor first); `D_inv`, its inverse pivots.
    With `looped_rnea`, the RNEA's part of rhs left to its loop, which reads the bodies' transforms
    `X`, gravity `g` and the acceleration `a`; with `looped_factor` also M's factor (the looped CRBA
    and factor), and a by the articulated-body algorithm (O(n)); with `low_rank` (a fixed-base chain,
    dofs in body order), no a: the loop forming M⁻¹ runs the RNEA's forces and takes Sᵀτ + Jᵀf − c − g
    to q̈ itself (articulated_inverse.py), where the traced part took the articulated-body algorithm's
    three passes, then one RNEA pass."""
    nv = m.robot.nv
    columns = _forward_dynamics_columns(m, looped_rnea)
    solved = [name for name in FORWARD_DYNAMICS_COLUMNS
              if not (name == "da_dtau" and tau_by_inverse(m.robot, len(columns["da_df"]), padded))]
    cols = [col for name in solved for col in columns[name]]
    terms = {"rhs": right_hand_side_rows(cols, nv)}
    if not looped_factor:
        parents = fd.dof_parents(m.robot)
        L, inv_diag = fd.ltdl(crba.mass_matrix(m), parents)
        terms.update(L=fd.packed_factor(L, parents), D_inv=inv_diag)
    if looped_rnea:
        terms.update(transforms_and_gravity(m), a=m.a)
        if m.feet:
            terms.update(feet_force_derivatives.axes_and_moments(m))
    if low_rank:  # q̈ comes from the loop (articulated_inverse.py)
        del terms["a"]
        return terms
    return replace_symbols(terms, m.a, aba.forward_dynamics_aba(m) if looped_factor else fd.forward_dynamics(m))



# The column blocks of contact_dynamics_derivatives: (∂a output, ∂λ output), in column order.
CONTACT_COLUMNS = (("da_dq", "dlambda_dq"), ("da_dv", "dlambda_dv"), ("da_dtau", "dlambda_dtau"))


def _contact_right_hand_sides(m):
    """The columns (r₁, r₂) of contact_dynamics_derivatives (contact_columns), r₂ the derivatives of
    the contact points' J a + J̇v at the placeholder a (feet_motion_derivatives)."""
    dq, dv = residual_derivatives(m)
    r2_q, r2_v = (_columns_of(rows, m.robot.nv) for rows in
                  feet_motion_derivatives.feet_acceleration_derivatives(m, m.contacts))
    return contact_columns(m.robot, dq, dv, r2_q, r2_v)


def _columns_of(rows, n):
    return [[row[c] for row in rows] for c in range(n)]


def contact_column_dofs(robot):
    """Per block of contact_columns (q, v, τ) the dof of each column."""
    joints = tuple(robot.joints[i].v_index for i in range(1, robot.nb))
    return tuple(range(robot.nv)), tuple(range(robot.nv)), joints


def contact_columns(robot, dq, dv, r2_q, r2_v):
    """The columns (r₁, r₂) of contact_dynamics_derivatives, q then v then τ (CONTACT_COLUMNS' order),
    from the forward-dynamics residual's derivatives dq, dv (rows) at placeholder a and f and r₂'s
    columns along q and v: r₁ = −Sᵀ and r₂ = 0 for τ."""
    nv = robot.nv
    selection = selection_columns(robot, -1.0)
    r1 = ([[dq[r][c] for r in range(nv)] for c in range(nv)]
          + [[dv[r][c] for r in range(nv)] for c in range(nv)] + selection)
    return r1, r2_q + r2_v + [sp.zeros(len(r2_q[0])) for _ in selection]


def at_contact_solution(m, named, delassus=cd.Delassus):
    """{name: expressions} with the placeholders a and f (m.tree_acceleration, the feet's forces)
    replaced by contact_dynamics' a and λ (`delassus` as in contact_dynamics)."""
    system = delassus(m)
    a, lam = cd.contact_dynamics(m, delassus)
    forces = [x for k in range(len(m.feet)) for x in m.foot_force(k)]
    return replace_symbols(named, list(m.tree_acceleration) + forces,
                           list(a) + system.feet_forces(m, lam))


def contact_dynamics_derivatives(m):
    """Differentiating both KKT rows of contact_dynamics at held (a, λ) gives
        [M −Jᵀ; J 0] [∂a; ∂λ] = −[r₁; r₂],  r₁ = ∂(RNEA(q, v, a) − Jᵀλ − Sᵀτ),  r₂ = ∂(J a + J̇v),
    solved as ∂λ = A⁻¹(J M⁻¹ r₁ − r₂), ∂a = M⁻¹(Jᵀ∂λ − r₁) with the Delassus factor (A = J M⁻¹Jᵀ),
    A⁻¹ as contact_dynamics' proximal solve in closed form (Delassus.step_sum: one solve with the
    factor and one 3nc × 3nc product per column instead of the proximal steps).
    r₁ is the forward-dynamics residual with placeholder symbols a and f (the per-foot λ), r₂ the
    tangents of the contact points' classical acceleration at the placeholder a; the placeholders
    take the contact_dynamics result last, as in forward_dynamics_derivatives."""
    robot = m.robot
    nv = robot.nv
    r1_columns, r2_columns = _contact_right_hand_sides(m)
    delassus = cd.Delassus(m)
    parents = fd.dof_parents(robot)
    L, inv_diag = fd.mass_matrix_factor(m)
    step_sum = delassus.step_sum()
    da, dlam = [], []
    for r1, r2 in zip(r1_columns, r2_columns):
        b = [sp.dot(delassus.Minv_Jt[r], r1) - r2[r] for r in range(len(r2))]
        dl = delassus.solve_many(step_sum, b)
        rhs = sp.vsub(sp.zeros(nv) if not dl else
                      [sp.dot([row[c] for row in delassus.J], dl) for c in range(nv)], r1)
        da.append(fd.ltdl_solve(L, inv_diag, parents, rhs, m.into_dof))
        dlam.append(dl)
    named, first = {}, 0
    for (a_name, l_name), width in zip(CONTACT_COLUMNS, (nv, nv, robot.n_joints)):
        named[a_name] = [x for col in da[first:first + width] for x in col]
        named[l_name] = [x for col in dlam[first:first + width] for x in col]
        first += width
    return at_contact_solution(m, named)


def contact_dynamics_derivative_terms(m):
    """What contact_dynamics_derivatives solves, unsolved (passes/looped_solve.py solves it in a loop):
    contact_terms of the scalar tree."""
    r1_columns, r2_columns = _contact_right_hand_sides(m)
    delassus = cd.Delassus(m)
    parents = fd.dof_parents(m.robot)
    L, inv_diag = fd.mass_matrix_factor(m)
    return at_contact_solution(m, contact_terms(r1_columns, r2_columns, delassus, *delassus.half_solves(m),
                                                fd.packed_factor(L, parents), inv_diag))


def contact_terms(r1_columns, r2_columns, damped, Z, D_inv_Z, L, D_inv, column_order=None):
    """The terms of contact_dynamics_derivatives' looped form, all row-major: `R1`, `R2`, the
    right-hand sides r₁ (nv rows) and r₂ (3nc rows) side by side, each row zero-padded to `padded`
    columns; `Zt_D`, (D⁻¹Z)ᵀ, and `Z`, Z = L⁻ᵀJᵀ (Delassus.half_solves, given as columns: one per
    contact row), with which the loops apply J M⁻¹ and M⁻¹Jᵀ between M⁻¹'s halves; the damped Delassus
    matrix F = L D Lᵀ of `damped` (a DampedSolve) as F⁻¹'s two halves, `F_U` = L⁻ᵀ and `F_DL` =
    D⁻¹L⁻¹ (rows padded like R2's: the loop multiplies them), and `mu`, its damping (the loop forms
    the proximal steps' closed form from them; contact_dynamics' steps already trace L⁻¹); `L`,
    `D_inv`, M's tree factor as in forward_dynamics_derivative_terms (L packed). `column_order`: the
    logical column at each place of R1 and R2 (limb_lanes.lane_column_order), else as given."""
    if column_order is not None:
        r1_columns, r2_columns = ([columns[c] for c in column_order] for columns in (r1_columns, r2_columns))
    nv = len(r1_columns[0])
    L_inv, D_inv_F = damped.lower_inverse, damped.factor[1]
    n = len(D_inv_F)
    zero = ex.const(0.0)
    return {"R1": right_hand_side_rows(r1_columns, nv), "R2": right_hand_side_rows(r2_columns, n),
            "Zt_D": [x for column in D_inv_Z for x in column],
            "Z": [column[r] for r in range(nv) for column in Z],
            "F_U": right_hand_side_rows([[L_inv[c][r] if r <= c else zero for r in range(n)] for c in range(n)], n,
                                        step_sum_columns(n)),
            "F_DL": right_hand_side_rows([[L_inv[r][c] * D_inv_F[r] if c <= r else zero for r in range(n)]
                                          for c in range(n)], n, step_sum_columns(n)),
            "mu": [damped.mu],
            "L": list(L), "D_inv": list(D_inv)}


def transforms_and_gravity(m):
    """What the looped RNEA derivatives read: each body's transform and gravity in root coordinates."""
    return {"X": crba.body_transforms(m), "g": m.gravity_in_base()}


def replace_symbols(named, symbols, values):
    """{name: expressions} with each symbol replaced by its value, all lists in one substitution
    (shared subexpressions rebuilt once); returns {name: tuple}."""
    placeholders = {node.id: value for node, value in zip(symbols, values)}
    entries = iter(substitute([x for xs in named.values() for x in xs], placeholders))
    return {name: tuple(next(entries) for _ in xs) for name, xs in named.items()}


def spec(robot, nf, nc):
    """trace.py's function table for the derivative quantities (nf feet, nc of them in contact):
    name → (doc, input names, [(output name, rows, cols, doc)], trace(m) → {output name:
    column-major entries})."""
    nv, nj, m3 = robot.nv, robot.n_joints, 3 * nc
    solved = 2 * nv + 3 * nf + (0 if tau_by_inverse(robot, 3 * nf, padded) else nj)  # the looped forms' columns
    on_q = "; columns: tangent δ of q ⊕ δ, ordered like v (docs/conventions.md)"
    tree_nv = tree_view(robot).nv  # the feet's force-term loop runs on a coupled robot's tree
    looped_feet = [("feet_axes", 3, tree_nv, "each (tree) dof's world axis (zero for a translation)"),
                   ("feet_moments", 3, tree_nv, "χ = Σ_k J_k × f_k per (tree) dof")] * (nf > 0)
    return {
        "inverse_dynamics_derivatives": (
            "Derivatives of the inverse dynamics τ = M a + c + g (∂τ/∂a is M).", ("q", "v", "a"),
            [("dtau_dq", nv, nv, "∂τ/∂q" + on_q), ("dtau_dv", nv, nv, "∂τ/∂v")],
            inverse_dynamics_derivatives),
        "bias_derivatives": (
            "Derivatives of the bias c + g (inverse dynamics at a = 0).", ("q", "v"),
            [("dbias_dq", nv, nv, "∂(c + g)/∂q" + on_q), ("dbias_dv", nv, nv, "∂c/∂v")],
            bias_derivatives),
        "gravity_derivatives": (
            "Derivative of the gravity terms g.", ("q",),
            [("dg_dq", nv, nv, "∂g/∂q" + on_q)], gravity_derivatives),
        "forward_dynamics_derivatives": (
            "Derivatives of the forward dynamics a = M⁻¹(Sᵀτ + Jᵀf − c − g): −M⁻¹ ∂(RNEA − τ_e) at "
            "(q, v, a), M⁻¹Sᵀ and M⁻¹Jᵀ, solved with the sparse LᵀDL factor of M.",
            ("q", "v", "tau", "f"),
            [("da_dq", nv, nv, "∂a/∂q" + on_q), ("da_dv", nv, nv, "∂a/∂v"),
             ("da_dtau", nv, nj, "∂a/∂τ = M⁻¹Sᵀ"),
             ("da_df", nv, 3 * nf, "∂a/∂f = M⁻¹Jᵀ; column 3k + r: foot k, world axis r")],
            forward_dynamics_derivatives),
        "forward_dynamics_derivative_terms": (
            "The traced part of forward_dynamics_derivatives in its looped form (passes/looped_solve.py).",
            ("q", "v", "tau", "f"),
            [("rhs", nv, padded(solved), "right-hand sides, row-major, zero-padded"),
             ("L", fd.factor_entries(robot), 1, "factor entries at each dof's ancestors"),
             ("D_inv", nv, 1, "inverse pivots")],
            forward_dynamics_derivative_terms),
        **{name: ("The traced part of %s in its looped form (passes/looped_rnea_derivatives.py)." % quantity,
                  inputs, [("X", 12, robot.nb - 1, "each body's transform (the body_transforms function's X)"),
                           ("g", 3, 1, "gravity in the root's coordinates")],
                  transforms_and_gravity)
           for name, quantity, inputs in (
               ("inverse_dynamics_derivative_transforms", "inverse_dynamics_derivatives", ("q", "v", "a")),
               ("bias_derivative_transforms", "bias_derivatives", ("q", "v")),
               ("gravity_derivative_transforms", "gravity_derivatives", ("q",)))},
        "forward_dynamics_derivative_loop_terms": (
            "The traced part of forward_dynamics_derivatives in its looped form with the looped RNEA "
            "derivatives (passes/looped_solve.py, looped_rnea_derivatives.py).",
            ("q", "v", "tau", "f"),
            [("rhs", nv, padded(solved), "right-hand sides without the RNEA's part, row-major"),
             ("L", fd.factor_entries(robot), 1, "factor entries at each dof's ancestors"),
             ("D_inv", nv, 1, "inverse pivots"),
             ("X", 12, robot.nb - 1, "each body's transform (the body_transforms function's X)"),
             ("g", 3, 1, "gravity in the root's coordinates"), ("a", nv, 1, "the forward dynamics' a")]
            + looped_feet,
            lambda m: forward_dynamics_derivative_terms(m, looped_rnea=True)),
        **{name: ("The traced part of forward_dynamics_derivatives in its %s (passes/looped_solve.py)." % form,
                  ("q", "v", "tau", "f"),
                  [("rhs", nv, padded(solved), "right-hand sides without the RNEA's part, row-major"),
                   ("X", 12, robot.nb - 1, "each body's transform (the body_transforms function's X)"),
                   ("g", 3, 1, "gravity in the root's coordinates")] + [last] * (last is not None) + looped_feet,
                  lambda m, low_rank=low_rank: forward_dynamics_derivative_terms(m, looped_rnea=True, looped_factor=True,
                                                                                  low_rank=low_rank))
           for name, form, last, low_rank in (
               ("forward_dynamics_derivative_tree_terms",
                "looped form with the looped CRBA, factor and RNEA derivatives",
                ("a", nv, 1, "the forward dynamics' a (articulated-body algorithm)"), False),
               ("forward_dynamics_derivative_chain_terms", "low-rank form", None, True))},
        "feet_velocity_derivatives": (
            "Derivative of the world foot velocities at fixed v.", ("q", "v"),
            [("dpdot_dq", 3 * nf, nv, "∂ṗ/∂q, rows 3k + r: foot k, world axis r" + on_q)],
            feet_velocity_derivatives),
        "feet_force_term_derivatives": (
            "Derivative of τ_e = Jᵀf at fixed world foot forces f.", ("q", "f"),
            [("dtau_e_dq", nv, nv, "∂(Jᵀf)/∂q" + on_q)], feet_force_term_derivatives),
        "feet_force_term_derivative_moments": (
            "The traced part of feet_force_term_derivatives in its looped form (passes/looped_feet_forces.py).",
            ("q", "f"), looped_feet, feet_force_derivatives.axes_and_moments),
        "contact_dynamics_derivative_terms": (
            "The traced part of contact_dynamics_derivatives in its looped form (passes/looped_solve.py).",
            ("q", "v", "tau"),
            [("R1", nv, padded(2 * nv + nj), "r₁ columns, row-major, zero-padded"),
             ("R2", m3, padded(2 * nv + nj), "r₂ columns, row-major, zero-padded"),
             ("Zt_D", m3, nv, "(D⁻¹Z)ᵀ, Z = L⁻ᵀJᵀ, row-major"), ("Z", nv, m3, "Z, row-major"),
             ("F_U", m3, step_sum_columns(m3), "L⁻ᵀ of the damped Delassus factor L D Lᵀ, row-major, zero-padded"),
             ("F_DL", m3, step_sum_columns(m3), "D⁻¹L⁻¹, row-major, zero-padded"),
             ("mu", 1, 1, "its damping μ"),
             ("L", fd.factor_entries(robot), 1, "M's factor entries at each dof's ancestors"),
             ("D_inv", nv, 1, "M's inverse pivots")],
            contact_dynamics_derivative_terms),
        "contact_dynamics_derivatives": (
            "Derivatives of contact_dynamics (a, λ): the KKT rows differentiated at the solution, "
            "solved through the Delassus factor (docs/runtime.md, \"Contact dynamics\").",
            ("q", "v", "tau"),
            [("da_dq", nv, nv, "∂a/∂q" + on_q), ("da_dv", nv, nv, "∂a/∂v"),
             ("da_dtau", nv, nj, "∂a/∂τ"),
             ("dlambda_dq", 3 * nc, nv, "∂λ/∂q, rows 3k + r: contact k, world axis r" + on_q),
             ("dlambda_dv", 3 * nc, nv, "∂λ/∂v"), ("dlambda_dtau", 3 * nc, nj, "∂λ/∂τ")],
            contact_dynamics_derivatives),
    }
