"""Forward dynamics: M a = Sᵀτ + τ_e − c − g (paper 000 Eq. 29-30) with M from the CRBA, the bias
from one RNEA pass and an unrolled sparse LᵀDL factorisation whose non-zeros are exactly the ones
the tree induces (no fill-in: row k of L is non-zero only at the ancestors of dof k)."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from ..views import coupled
from .crba import mass_matrix
from .rnea import bias, bias_minus_external


def dof_parents(robot):
    """λ over degrees of freedom: the six trunk dofs form a chain (their block is dense), each joint
    dof hangs from the last dof of its parent body; a coupled robot's over its independent dofs
    (views/coupled.py)."""
    if robot.couplings:
        return coupled.dof_parents(robot, dof_parents(coupled.tree_view(robot)))
    parents = []
    if robot.floating_base:
        parents = [-1, 0, 1, 2, 3, 4]
    for i in range(1, robot.nb):
        p = robot.parent[i]
        if p == 0:
            parents.append(5 if robot.floating_base else -1)
        else:
            parents.append(robot.joints[p].v_index)
    return parents


def dof_ancestors(parents, i):
    """The dofs above dof i in the tree, nearest first."""
    out = []
    j = parents[i]
    while j != -1:
        out.append(j)
        j = parents[j]
    return out


def dof_depths(parents):
    """len(dof_ancestors(parents, i)) of every dof i, each parent's reused."""
    depth = [None] * len(parents)
    for i in range(len(parents)):
        path, j = [], i
        while j != -1 and depth[j] is None:  # up to the first dof already known
            path.append(j)
            j = parents[j]
        d = -1 if j == -1 else depth[j]
        for k in reversed(path):
            d += 1
            depth[k] = d
    return depth


def _as_is(k, i, value):
    return value


def ltdl(H, parents, into=_as_is):
    """In place M = Lᵀ D L over the tree's dof parents (Featherstone's LTDL): returns (L, D) with L
    unit lower triangular stored below the diagonal of H and D its diagonal; inverse pivots are
    computed once each. into(k, i, term): dof k's term as it updates dof i's entries (the lane sum
    where a lane limb meets the trunk, TracedModel.into_dof)."""
    n = len(H)
    H = [list(row) for row in H]
    inv_diag = [None] * n
    for k in range(n - 1, -1, -1):
        inv_diag[k] = ex.const(1.0) / H[k][k]
        i = parents[k]
        while i != -1:
            ratio = H[k][i] * inv_diag[k]
            j = i
            while j != -1:
                H[i][j] = H[i][j] - into(k, i, ratio * H[k][j])
                j = parents[j]
            H[k][i] = ratio
            i = parents[i]
    return H, inv_diag


def ltdl_solve(L, inv_diag, parents, b, into=_as_is):
    """Solves Lᵀ D L x = b: x ← L⁻ᵀ b, x ← D⁻¹ x, x ← L⁻¹ x, walking only tree non-zeros (`into` as
    in ltdl)."""
    x = ltdl_eliminate(L, inv_diag, parents, b, into)
    return ltdl_substitute(L, parents, x, range(len(x)))


def ltdl_eliminate(L, inv_diag, parents, b, into=_as_is):
    """The first two steps of ltdl_solve: D⁻¹ L⁻ᵀ b (leaves to root)."""
    return [x * d for x, d in zip(ltdl_forward(L, parents, b, into), inv_diag)]


def ltdl_forward(L, parents, b, into=_as_is):
    """The first step of ltdl_solve, L⁻ᵀ b (leaves to root): non-zero only on the ancestors of b's
    non-zeros."""
    x = list(b)
    for i in range(len(x) - 1, -1, -1):
        j = parents[i]
        while j != -1:
            x[j] = x[j] - into(i, j, L[i][j] * x[i])
            j = parents[j]
    return x


def ltdl_substitute(L, parents, x, dofs):
    """The last step of ltdl_solve, x ← L⁻¹ x, for the entries `dofs` (root to leaves; their
    ancestors' entries of x final)."""
    x = list(x)
    for i in dofs:
        j = parents[i]
        while j != -1:
            x[i] = x[i] - L[i][j] * x[j]
            j = parents[j]
    return x


def packed_factor(L, parents):
    """L's entries at each dof's tree ancestors, dof by dof, nearest ancestor first (the layout
    rbdc_gen/solve.hpp's ltdl_solve_columns reads); one unused zero when no dof has an ancestor, so
    the array stays legal C++."""
    n = len(parents)
    return [L[i][j] for i in range(n) for j in dof_ancestors(parents, i)] or [ex.const(0.0)]


def packed_starts(parents):
    """Where each dof's entries start in packed_factor's layout, and one past the last."""
    starts = [0]
    for i in range(len(parents)):
        starts.append(starts[-1] + len(dof_ancestors(parents, i)))
    return starts


def factor_entries(robot):
    """How many entries packed_factor holds (at least one)."""
    parents = dof_parents(robot)
    return max(sum(dof_depths(parents)), 1)


def factor_outputs(L, inv_diag, parents):
    """The factor as outputs: L (unit lower triangular, zero off the dof tree's ancestor entries),
    its pivots D and their inverses D⁻¹ (computed once by ltdl; a solve multiplies by them)."""
    n = len(L)
    zero, one = ex.const(0.0), ex.const(1.0)
    rows = [[one if c == r else zero for c in range(n)] for r in range(n)]
    for r in range(n):
        c = parents[r]
        while c != -1:
            rows[r][c] = L[r][c]
            c = parents[c]
    return {"L": tuple(rows[r][c] for c in range(n) for r in range(n)),
            "D": tuple(L[k][k] for k in range(n)), "D_inv": tuple(inv_diag)}


def factor_terms(m):
    """What ltdl reads of M, for a factorisation done by a loop (passes/looped_factor.py): M's
    entries at each dof's ancestors in packed_factor's layout, and its diagonal."""
    H = mass_matrix(m)
    parents = dof_parents(m.robot)
    return {"L": tuple(packed_factor(H, parents)), "D": tuple(H[k][k] for k in range(len(H)))}


def mass_matrix_factor(m):
    """M = Lᵀ D L over the dof tree, M from the CRBA: (L with the pivots on its diagonal, D⁻¹)."""
    H = mass_matrix(m)
    m.mark("factorisation M = LᵀDL")
    return ltdl(H, dof_parents(m.robot), m.into_dof)


def forward_dynamics(m):
    return _solve_with_torques(m, bias_minus_external(m))   # c + g − τ_e


def free_acceleration(m):
    """a₀ = M⁻¹(Sᵀτ − c − g): the forward dynamics without foot forces (no f input)."""
    return _solve_with_torques(m, bias(m))


def torques_minus(m, h):
    """Sᵀτ − h for the generalised forces h, trunk then joints in body order (the unactuated trunk:
    Sᵀτ has zeros there)."""
    robot = m.robot
    return ([-b for b in h[:robot.root_dofs]]
            + [m.tau[i - 1] - h[robot.joints[i].v_index] for i in range(1, robot.nb)])


def _solve_with_torques(m, h):
    """M⁻¹(Sᵀτ − h) for the generalised forces h."""
    robot = m.robot
    rhs = torques_minus(m, h)
    parents = dof_parents(robot)
    L, inv_diag = mass_matrix_factor(m)
    m.mark("solve LᵀDL a = τ + τ_e − c − g")
    return tuple(ltdl_solve(L, inv_diag, parents, rhs, m.into_dof))


def mass_matrix_inverse(m):
    """M⁻¹ (rows) as the Gram matrix of the unit columns through half of M's solve (half_solve_gram),
    each entry of the symmetric inverse computed once."""
    n = m.robot.nv
    L, inv_diag = mass_matrix_factor(m)
    zero, one = ex.const(0.0), ex.const(1.0)
    m.mark("M⁻¹ through half of M's solve")
    identity = [[one if r == k else zero for r in range(n)] for k in range(n)]
    return half_solve_gram(L, inv_diag, dof_parents(m.robot), identity, m.into_dof)[0]


def lane_mass_matrix_inverse(m):
    """M⁻¹ (the full robot's rows) on the quadruped's lane model (views/limb_lanes.py), as
    mass_matrix_inverse: Zᵀ D⁻¹ Z, Z = L⁻ᵀ of the unit columns. A trunk column's Z is scalar and non-zero
    on the trunk only; a limb column's is a lane value (lane k: that column of limb k), non-zero on its
    limb and the trunk, kept apart per lane (no lane sum). So a trunk-limb entry is a lane dot product
    over the trunk (four entries at once), and two limb columns meet as in lane_gram."""
    parents = dof_parents(m.robot)
    L, inv_diag = mass_matrix_factor(m)
    n, root = m.robot.nv, m.robot.root_dofs
    zero, one = ex.const(0.0), ex.const(1.0)
    m.mark("M⁻¹ through half of M's solve, the limbs' columns in lanes")
    Z = [ltdl_forward(L, parents, [one if i == j else zero for i in range(n)]) for j in range(n)]
    D_inv_Z = [[z * d for z, d in zip(column, inv_diag)] for column in Z]
    trunk, limb = range(root), range(root, n)
    full = [[None] * m.full.nv for _ in range(m.full.nv)]
    for r in trunk:
        for s in range(r + 1):  # symmetric: each entry once
            full[r][s] = full[s][r] = sp.dot(Z[r][:root], D_inv_Z[s][:root])
        for s in limb:
            entries = sp.dot(Z[r][:root], D_inv_Z[s][:root])
            for k in range(ex.LANES):
                full[r][m.full_index(s, k)] = full[m.full_index(s, k)][r] = ex.lane_get(entries, k)
    gram = lane_gram([Z[j] for j in limb], [D_inv_Z[j] for j in limb], trunk)
    for a, r in enumerate(limb):
        for b, s in enumerate(limb):
            for k in range(ex.LANES):
                for l in range(ex.LANES):
                    full[m.full_index(r, k)][m.full_index(s, l)] = lane_gram_entry(gram, a, k, b, l)
    return full


def lane_gram(Z, D_inv_Z, trunk):
    """The Gram entries Z_rᵀ D⁻¹ Z_s of lane columns (lane k: a column of limb k, non-zero on limb k and
    the trunk): gram[δ][r][s], lane k, is column r of limb k against column s of limb k + δ. δ = 0 sums
    over all dofs (symmetric in r and s: each entry once); δ ≠ 0 over the trunk's only (two limbs meet
    there), the second operand's lanes rotated. δ ≤ LANES/2 covers every pair of lanes
    (lane_gram_entry)."""
    n = len(Z)
    same = [[None] * n for _ in range(n)]
    for r in range(n):
        for s in range(r + 1):
            same[r][s] = same[s][r] = sp.dot(Z[r], D_inv_Z[s])
    gram = [same]
    for delta in range(1, ex.LANES // 2 + 1):
        gram.append([[sp.dot([z[t] for t in trunk], [ex.lane_rotate(d[t], delta) for t in trunk])
                      for d in D_inv_Z] for z in Z])
    return gram


def lane_gram_entry(gram, r, k, s, l):
    """Column r of limb k against column s of limb l, from lane_gram."""
    delta = (l - k) % ex.LANES
    return (ex.lane_get(gram[delta][r][s], k) if delta < len(gram) else
            ex.lane_get(gram[ex.LANES - delta][s][r], l))


def half_solve_gram(L, inv_diag, parents, columns, into=_as_is):
    """(Bᵀ M⁻¹ B as symmetric rows, Z, D⁻¹Z) for the columns of B, M = Lᵀ D L: with Z = L⁻ᵀB (a column
    non-zero only on the tree ancestors of its non-zeros) entry (r, s) is Z_rᵀ D⁻¹ Z_s, a sum over
    their common ancestors independent of the other entries; M⁻¹B = L⁻¹ D⁻¹Z when it is needed."""
    Z = [ltdl_forward(L, parents, b, into) for b in columns]
    D_inv_Z = [[z * d for z, d in zip(column, inv_diag)] for column in Z]
    n = len(columns)
    gram = [[None] * n for _ in range(n)]
    for r in range(n):
        for s in range(r + 1):
            gram[r][s] = gram[s][r] = sp.dot(Z[r], D_inv_Z[s])
    return gram, Z, D_inv_Z
