"""Mimic couplings in the generator (docs/model.md, "Mimic joints"): q_f = m·q_l + o.

The IR describes the tree; `load_ir` gives the generator the robot in its independent coordinates
(the tree's without the followers', order kept; a follower's q_index/v_index are its leader's), the
coordinates of the generated signatures. Tracing runs the tree algorithms on `tree_view(robot)`
with the inputs expanded (q_tree = expand(q), v_tree = G v, a_tree = G a, multiplier and offset as
constants) and projects the outputs: M' = Gᵀ M G, c' = Gᵀ c, g' = Gᵀ g, τ' = Gᵀ τ, J' = J G.
G is constant, so the projection adds no velocity-product term.
"""
from __future__ import annotations

from dataclasses import replace

from . import expr as ex
from .algorithms.crba import mass_matrix
from .algorithms.forward_dynamics import factor_outputs, ltdl, ltdl_solve
from .algorithms.rnea import bias_minus_external
from .errors import RbdcError

# Output names whose rows (resp. columns) are velocity coordinates: Gᵀ from the left (resp. G from
# the right). Positions and velocities of points need nothing.
_ROWS_IN_V = {"c", "g", "cg", "tau_e", "tau", "M"}
_COLS_IN_V = {"J", "M"}
_PROJECTED = {"feet_positions", "feet_velocities", "feet_jacobian", "quadratic_velocity_terms",
              "gravity_terms", "bias", "feet_force_terms", "inverse_dynamics", "mass_matrix"}


def _root(robot):
    return (7, 6) if robot.floating_base else (0, 0)


def independent_view(tree):
    """The robot in independent coordinates; `tree` as the IR describes it (tree indices)."""
    if not tree.couplings:
        return tree
    q0, v0 = _root(tree)
    followers = {c.follower: c for c in tree.couplings}
    index, joints = {}, list(tree.joints)
    for i in range(1, tree.nb):
        if i not in followers:
            index[i] = len(index)
    for i in range(1, tree.nb):
        k = index[followers[i].leader if i in followers else i]
        joints[i] = replace(joints[i], q_index=q0 + k, v_index=v0 + k)
    return replace(tree, nq=q0 + len(index), nv=v0 + len(index), joints=tuple(joints))


def tree_view(robot):
    """The tree with every joint a coordinate of its own (the IR's numbering), no couplings."""
    if not robot.couplings:
        return robot
    q0, v0 = _root(robot)
    joints = [robot.joints[0]] + [replace(j, q_index=q0 + i - 1, v_index=v0 + i - 1)
                                  for i, j in enumerate(robot.joints[1:], start=1)]
    return replace(robot, nq=q0 + robot.nb - 1, nv=v0 + robot.nb - 1, joints=tuple(joints), couplings=())


def expand(robot, name, values):
    """Tree-sized q (name 'q': q_f = m·q_l + o) or v/a (G v) from the independent inputs."""
    if not robot.couplings:
        return values
    coupling = {c.follower: c for c in robot.couplings}
    q0, v0 = _root(robot)
    start = q0 if name == "q" else v0
    out = list(values[:start])
    for i in range(1, robot.nb):
        j = robot.joints[i]
        x = values[j.q_index if name == "q" else j.v_index]
        if i in coupling:
            x = coupling[i].multiplier * x + (coupling[i].offset if name == "q" else 0.0)
        out.append(x)
    return tuple(out)


def _g_columns(robot):
    """G as, per tree velocity row, (independent column, weight)."""
    coupling = {c.follower: c.multiplier for c in robot.couplings}
    _, v0 = _root(robot)
    rows = [(k, 1.0) for k in range(v0)]
    rows += [(robot.joints[i].v_index, coupling.get(i, 1.0)) for i in range(1, robot.nb)]
    return rows


def _project(values, rows, cols, project_rows, project_cols, g, n):
    """Gᵀ X (project_rows) and/or X G (project_cols) of a column-major rows × cols matrix."""
    matrix = [[values[c * rows + r] for c in range(cols)] for r in range(rows)]
    if project_rows:
        out = [[0.0] * cols for _ in range(n)]
        for r, (k, w) in enumerate(g):
            out[k] = [a + w * b for a, b in zip(out[k], matrix[r])]
        matrix, rows = out, n
    if project_cols:
        out = [[0.0] * n for _ in range(rows)]
        for r in range(rows):
            for c, (k, w) in enumerate(g):
                out[r][k] = out[r][k] + w * matrix[r][c]
        matrix, cols = out, n
    return tuple(ex.lift(matrix[r][c]) for c in range(cols) for r in range(rows))


def traced_values(robot, name, m, build, output_specs):
    """The outputs of function `name` in independent coordinates: `build(m)` traces the tree
    algorithm (m's inputs already expanded), then each output is projected with G."""
    if not robot.couplings:
        return build(m)
    if name == "forward_dynamics":
        return {"a": _forward_dynamics(robot, m)}
    if name == "mass_matrix_factor":
        return _mass_matrix_factor(robot, m)
    if name not in _PROJECTED:
        raise RbdcError("robot '%s': %s is not supported with mimic couplings (%d coupled joints); "
                        "load the mimic joints locked (--lock-mimic) or independent (--independent-mimic)"
                        % (robot.name, name, len(robot.couplings)))
    tree = tree_view(robot)
    g, values = _g_columns(robot), build(m)
    for output, _, cols, _ in output_specs:
        rows_in_v, cols_in_v = output in _ROWS_IN_V, output in _COLS_IN_V
        if not (rows_in_v or cols_in_v):
            continue
        rows = tree.nv if rows_in_v else len(values[output]) // (tree.nv if cols_in_v else cols)
        tree_cols = tree.nv if cols_in_v else cols
        values[output] = _project(values[output], rows, tree_cols, rows_in_v, cols_in_v, g, robot.nv)
    return values


def _projected_mass_matrix(robot, m):
    """M' = Gᵀ M G as rows."""
    nv, n = tree_view(robot).nv, robot.nv
    M = mass_matrix(m)
    M_flat = tuple(M[r][c] for c in range(nv) for r in range(nv))
    projected = _project(M_flat, nv, nv, True, True, g=_g_columns(robot), n=n)
    return [[projected[c * n + r] for c in range(n)] for r in range(n)]


def _dense_chain(n):
    """Each dof's parent is the previous one: couplings join branches, so M' has no tree
    sparsity to exploit and is factorised densely."""
    return list(range(-1, n - 1))


def _mass_matrix_factor(robot, m):
    """M' = Lᵀ D L, dense."""
    chain = _dense_chain(robot.nv)
    return factor_outputs(*ltdl(_projected_mass_matrix(robot, m), chain), chain)


def _forward_dynamics(robot, m):
    """a' = M'⁻¹(S'ᵀτ' − Gᵀ(c + g − τ_e)) with M' = Gᵀ M G, factorised densely."""
    tree = tree_view(robot)
    nv, n = tree.nv, robot.nv
    M_ind = _projected_mass_matrix(robot, m)
    bias = _project(tuple(bias_minus_external(m)), nv, 1, True, False, _g_columns(robot), n)
    root = robot.root_dofs
    rhs = [-b for b in bias[:root]] + [m.tau[k - root] - bias[k] for k in range(root, n)]
    chain = _dense_chain(n)
    L, inv_diag = ltdl(M_ind, chain)
    return tuple(ltdl_solve(L, inv_diag, chain, rhs))
