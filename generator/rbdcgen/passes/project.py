"""Mimic couplings in the generator (docs/model.md, "Mimic joints"): q_f = m·q_l + o.

The IR describes the tree; `load_ir` gives the generator the robot in its independent coordinates
(the tree's without the followers', order kept; a follower's q_index/v_index are its leader's), the
coordinates of the generated signatures. Tracing runs the tree algorithms on `tree_view(robot)`
with the inputs expanded (q_tree = expand(q), v_tree = G v, a_tree = G a, multiplier and offset as
constants) and projects the outputs: M' = Gᵀ M G, c' = Gᵀ c, g' = Gᵀ g, τ' = Gᵀ τ, J' = J G.
G is constant, so the projection adds no velocity-product term, and a derivative projects the same
way: ∂τ'/∂q' = Gᵀ (∂τ/∂q) G (the expansion's Jacobian is G, on the manifold too: a follower is a
joint). The forward-dynamics derivatives keep their method (differentiate.py) in the independent
coordinates: the tree's residual derivatives at a_tree = G a', projected, solved with M'.
"""
from __future__ import annotations

from ..graph import expr as ex
from ..algorithms.crba import mass_matrix
from ..algorithms.feet_force_derivatives import axes_and_moments
from ..algorithms.jacobian import feet_jacobian
from ..algorithms.rnea_derivatives import has_rotors
from ..algorithms.forward_dynamics import dof_parents, factor_outputs, ltdl, ltdl_solve, packed_factor
from ..algorithms.rnea import bias_minus_external
from ..errors import RbdcError
from ..views.coupled import tree_view, velocity_columns
from .differentiate import (FORWARD_DYNAMICS_COLUMNS, replace_symbols, residual_derivatives, right_hand_side_rows,
                             transforms_and_gravity)

# Output names whose rows (resp. columns) are velocity coordinates: Gᵀ from the left (resp. G from
# the right). Positions and velocities of points need nothing.
# A derivative of a v-vector along q or v tangents has both.
_DERIVATIVES_IN_V = {"dtau_dq", "dtau_dv", "dbias_dq", "dbias_dv", "dg_dq", "dtau_e_dq"}
_ROWS_IN_V = {"c", "g", "cg", "tau_e", "tau", "M"} | _DERIVATIVES_IN_V
_COLS_IN_V = {"J", "M", "dpdot_dq"} | _DERIVATIVES_IN_V
# Derivatives come from the analytic recursions only: the tangent-propagated ones (any derivative of
# a robot with rotors) seed the tree's coordinates, which a coupled robot's expanded inputs are not.
_ANALYTIC_DERIVATIVES = {"inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives",
                         "feet_force_term_derivatives", "feet_velocity_derivatives"}
# The looped RNEA derivatives' traced part (bodies' transforms and gravity: nothing in v) and the feet
# force-term loop's (axes and moments) run on the tree as it is; their loops project
# (passes/looped_rnea_derivatives.py, looped_feet_forces.py).
_TREE_TERMS = {"inverse_dynamics_derivative_transforms", "bias_derivative_transforms",
               "gravity_derivative_transforms", "feet_force_term_derivative_moments"}
_PROJECTED = {"feet_positions", "feet_velocities", "feet_jacobian", "quadratic_velocity_terms",
              "gravity_terms", "bias", "feet_force_terms", "inverse_dynamics",
              "mass_matrix"} | _ANALYTIC_DERIVATIVES


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
    if not robot.couplings or name in _TREE_TERMS:
        return build(m)
    if name == "forward_dynamics":
        return {"a": _forward_dynamics(robot, m)}
    if name == "mass_matrix_factor":
        return _mass_matrix_factor(robot, m)
    if name in _ANALYTIC_DERIVATIVES | {"forward_dynamics_derivatives"} and has_rotors(m.robot):
        raise RbdcError("robot '%s': %s is not supported with mimic couplings and rotors together"
                        % (robot.name, name))
    if name == "forward_dynamics_derivatives":
        return _forward_dynamics_derivatives(robot, m)
    if name == "forward_dynamics_derivative_terms":
        return _forward_dynamics_derivative_terms(robot, m)
    if name == "forward_dynamics_derivative_loop_terms":
        return _forward_dynamics_derivative_terms(robot, m, looped_rnea=True)
    if name not in _PROJECTED:
        raise RbdcError("robot '%s': %s is not supported with mimic couplings (%d coupled joints); "
                        "load the mimic joints locked (--lock-mimic) or independent (--independent-mimic)"
                        % (robot.name, name, len(robot.couplings)))
    tree = tree_view(robot)
    g, values = velocity_columns(robot), build(m)
    for output, _, cols, _ in output_specs:
        rows_in_v, cols_in_v = output in _ROWS_IN_V, output in _COLS_IN_V
        if not (rows_in_v or cols_in_v):
            continue
        rows = tree.nv if rows_in_v else len(values[output]) // (tree.nv if cols_in_v else cols)
        tree_cols = tree.nv if cols_in_v else cols
        values[output] = _project(values[output], rows, tree_cols, rows_in_v, cols_in_v, g, robot.nv)
    return values


def _projected_square(robot, rows):
    """Gᵀ X G of a tree nv × nv matrix given as rows, as rows."""
    nv, n = tree_view(robot).nv, robot.nv
    flat = tuple(rows[r][c] for c in range(nv) for r in range(nv))
    projected = _project(flat, nv, nv, True, True, g=velocity_columns(robot), n=n)
    return [[projected[c * n + r] for c in range(n)] for r in range(n)]


def _projected_mass_matrix(robot, m):
    """M' = Gᵀ M G as rows."""
    return _projected_square(robot, mass_matrix(m))


def _mass_matrix_factor(robot, m):
    """M' = Lᵀ D L over the independent dofs' tree (dof_parents: dense where couplings join branches)."""
    parents = dof_parents(robot)
    return factor_outputs(*ltdl(_projected_mass_matrix(robot, m), parents), parents)


def _forward_dynamics(robot, m):
    """a' = M'⁻¹(S'ᵀτ' − Gᵀ(c + g − τ_e)) with M' = Gᵀ M G, factorised densely."""
    tree = tree_view(robot)
    nv, n = tree.nv, robot.nv
    M_ind = _projected_mass_matrix(robot, m)
    bias = _project(tuple(bias_minus_external(m)), nv, 1, True, False, velocity_columns(robot), n)
    root = robot.root_dofs
    rhs = [-b for b in bias[:root]] + [m.tau[k - root] - bias[k] for k in range(root, n)]
    parents = dof_parents(robot)
    L, inv_diag = ltdl(M_ind, parents)
    return tuple(ltdl_solve(L, inv_diag, parents, rhs))


def _forward_dynamics_derivative_columns(robot, m, looped_rnea=False):
    """{output: columns} of forward_dynamics_derivatives before M'⁻¹: −Gᵀ ∂(RNEA − τ_e) G at
    a_tree = G a' (a' the placeholder), S'ᵀ and (J G)ᵀ. With `looped_rnea` the ∂q and ∂v columns
    are zero: the looped RNEA derivatives subtract the RNEA's part and a loop adds ∂τ_e/∂q, both
    projected (passes/looped_rnea_derivatives.py, looped_feet_forces.py)."""
    n, root = robot.nv, robot.root_dofs
    if looped_rnea:
        zero = ex.const(0.0)
        columns = {"da_dq": [[zero] * n for _ in range(n)], "da_dv": [[zero] * n for _ in range(n)]}
    else:
        dq, dv = (_projected_square(robot, x) for x in residual_derivatives(m))
        columns = {"da_dq": [[-dq[r][c] for r in range(n)] for c in range(n)],
                   "da_dv": [[-dv[r][c] for r in range(n)] for c in range(n)]}
    columns["da_dtau"] = [[ex.const(1.0 if r == root + k else 0.0) for r in range(n)]
                          for k in range(robot.n_joints)]                            # S'ᵀ
    J = feet_jacobian(m) if m.feet else []
    tree_nv = tree_view(robot).nv
    JG = _project(tuple(J[r][c] for c in range(tree_nv) for r in range(len(J))), len(J), tree_nv,
                  False, True, velocity_columns(robot), n)
    columns["da_df"] = [[JG[c * len(J) + row] for c in range(n)] for row in range(len(J))]  # (J G)ᵀ
    return columns


def _forward_dynamics_derivatives(robot, m):
    """∂a'/∂(q', v', τ', f) = M'⁻¹ applied to _forward_dynamics_derivative_columns, with the
    placeholders a' replaced by the forward dynamics afterwards (differentiate.py's method)."""
    parents = dof_parents(robot)
    L, inv_diag = ltdl(_projected_mass_matrix(robot, m), parents)
    solved = {name: [x for col in cols for x in ltdl_solve(L, inv_diag, parents, col)]
              for name, cols in _forward_dynamics_derivative_columns(robot, m).items()}
    return replace_symbols(solved, m.input("a", robot.nv), _forward_dynamics(robot, m))


def _forward_dynamics_derivative_terms(robot, m, looped_rnea=False):
    """What the looped form of forward_dynamics_derivatives solves (differentiate.
    forward_dynamics_derivative_terms' outputs) in the independent coordinates: the columns
    unsolved, M''s factor over dof_parents, its inverse pivots; with `looped_rnea` also what that
    loop reads, the tree's transforms and gravity, and a'."""
    columns = _forward_dynamics_derivative_columns(robot, m, looped_rnea)
    parents = dof_parents(robot)
    L, inv_diag = ltdl(_projected_mass_matrix(robot, m), parents)
    a = m.input("a", robot.nv)
    terms = {"rhs": right_hand_side_rows([col for name in FORWARD_DYNAMICS_COLUMNS for col in columns[name]],
                                         robot.nv),
             "L": packed_factor(L, parents), "D_inv": inv_diag}
    if looped_rnea:
        terms.update(transforms_and_gravity(m), a=a)
        if m.feet:
            terms.update(axes_and_moments(m))
    return replace_symbols(terms, a, _forward_dynamics(robot, m))
