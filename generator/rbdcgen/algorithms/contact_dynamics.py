"""Rigid-contact and impulse dynamics for the scene's contact feet (runtime/include/rbdc/
contact_dynamics.hpp; docs/runtime.md, "Contact dynamics"). The KKT systems

    M a − Jᵀλ = Sᵀτ − c − g,  J a = −J̇v          M (v⁺ − v⁻) = JᵀΛ,  J v⁺ = −e J v⁻

are solved through their Schur complement, the Delassus matrix A = J M⁻¹Jᵀ (M⁻¹Jᵀ by the sparse
LᵀDL factor of forward_dynamics), with the runtime's damping: A + μ1 factorised once (dense LDLᵀ of
the small contact block), μ = DAMPING_RELATIVE · tr(A)/m + DAMPING_FLOOR, and PROXIMAL_STEPS proximal
steps λ ← λ + (A + μ1)⁻¹(b − A λ) from λ = 0. Redundant contacts (a singular A) then give the
least-norm λ instead of a division by zero. On the lane model (one contact foot per limb) the
Delassus matrix is built by LaneDelassus, the damped solve being the same (DampedSolve)."""

from __future__ import annotations

from functools import cached_property

from ..graph import expr as ex
from ..graph import spatial as sp
from . import forward_dynamics as fd
from .jacobian import feet_jacobian
from .frames import feet_bias_accelerations

# The runtime's kContactDampingRelative, kContactDampingFloor, kContactProximalSteps.
DAMPING_RELATIVE = 1e-5
DAMPING_FLOOR = 1e-30
PROXIMAL_STEPS = 5


def contact_rows(m, feet_rows):
    """The rows (3 per contact, contact-major) of a 3·n_feet-row quantity, in the scene's contact
    order."""
    rows = []
    for foot in m.contacts:
        k = m.feet.index(foot)
        rows += feet_rows[3 * k:3 * k + 3]
    return rows


def dense_ldlt(A):
    """A = L D Lᵀ of a symmetric positive definite matrix (rows), L unit lower triangular: (L,
    inverse pivots). Dense: the contact block has no tree sparsity to exploit. Each entry's sum reads
    the other row's entries before their division by the pivot (LD = L·D): one multiplication per
    term instead of two (the Mini Cheetah's 12 × 12: 286 fewer)."""
    n = len(A)
    L = [[None] * n for _ in range(n)]
    LD = [[None] * n for _ in range(n)]
    inv_d = [None] * n
    for j in range(n):
        pivot = A[j][j]
        for k in range(j):
            pivot = pivot - L[j][k] * LD[j][k]
        inv_d[j] = ex.const(1.0) / pivot
        for i in range(j + 1, n):
            x = A[i][j]
            for k in range(j):
                x = x - L[i][k] * LD[j][k]
            LD[i][j], L[i][j] = x, x * inv_d[j]
    return L, inv_d


def ldlt_solve(L, inv_d, b):
    """x = L⁻ᵀ D⁻¹ L⁻¹ b."""
    n = len(b)
    y = list(b)
    for i in range(n):
        for k in range(i):
            y[i] = y[i] - L[i][k] * y[k]
    x = [y[i] * inv_d[i] for i in range(n)]
    for i in range(n - 1, -1, -1):
        for k in range(i + 1, n):
            x[i] = x[i] - L[k][i] * x[k]
    return x


def unit_lower_inverse(L):
    """L⁻¹ of a unit lower triangular L (rows, its strict lower triangle read), column by column:
    L⁻¹[i][j] = −Σ_{j≤k<i} L[i][k] L⁻¹[k][j]."""
    n = len(L)
    inverse = [[ex.const(1.0 if i == j else 0.0) for j in range(n)] for i in range(n)]
    for j in range(n):
        for i in range(j + 1, n):
            x = ex.const(0.0)
            for k in range(j, i):
                x = x - L[i][k] * inverse[k][j]
            inverse[i][j] = x
    return inverse


def _transpose(rows):
    return [list(column) for column in zip(*rows)]


class DampedSolve:
    """The damped Delassus system of A (symmetric rows, contact order): A + μ1 factorised once
    (dense LDLᵀ), μ = DAMPING_RELATIVE · tr(A)/m + DAMPING_FLOOR, and its proximal solve."""

    def __init__(self, A):
        self.A = A
        n = len(A)
        trace = ex.const(0.0)
        for r in range(n):
            trace = trace + A[r][r]
        self.mu = ex.const(DAMPING_RELATIVE / n) * trace + ex.const(DAMPING_FLOOR)
        damped = [[A[r][s] + self.mu if r == s else A[r][s] for s in range(n)] for r in range(n)]
        self.factor = dense_ldlt(damped)

    def solve(self, b):
        """A x = b by the proximal steps x ← x + F⁻¹(b − A x) from x = 0 (F = A + μ1), each taken as
        x ← F⁻¹(b + μ x), the same step without the product A x, and F⁻¹ = L⁻ᵀ D⁻¹ L⁻¹ applied as
        two products with L⁻¹, formed once: a substitution chains each entry through every earlier
        one, and five of them in a row were latency bound (docs/performance.md, "The Delassus
        steps as products")."""
        L_inv, inv_d = self.lower_inverse, self.factor[1]
        n = len(b)
        x = None
        for _ in range(PROXIMAL_STEPS):
            r = list(b) if x is None else [b_r + self.mu * x_r for b_r, x_r in zip(b, x)]
            y = [sp.dot(L_inv[i][:i + 1], r[:i + 1]) * inv_d[i] for i in range(n)]
            x = [sp.dot([L_inv[k][i] for k in range(i, n)], y[i:]) for i in range(n)]
        return x

    @cached_property
    def lower_inverse(self):
        """L⁻¹ of the factor's unit lower triangle (rows)."""
        return unit_lower_inverse(self.factor[0])

    def step_sum(self):
        """Q = Σ_{j<PROXIMAL_STEPS} Gʲ, G = 1 − F⁻¹A (F = A + μ1), built by Horner's rule: the proximal
        steps are linear in b, x_{k+1} = G x_k + F⁻¹b, so solve(b) = Q F⁻¹b. G's eigenvalues are
        μ/(aᵢ + μ) ∈ (0, 1], so Q is bounded (≤ PROXIMAL_STEPS) even for redundant contacts, where F⁻¹
        is not; F⁻¹b stays a solve with the factor. For many right-hand sides
        (contact_dynamics_derivatives: 2·nv + n_joints of them) one Q costs ~m³ per step once against
        m² per step for each solve."""
        n = len(self.A)
        H = _transpose([ldlt_solve(*self.factor, [row[s] for row in self.A]) for s in range(n)])
        G = [[ex.const(1.0 if r == s else 0.0) - H[r][s] for s in range(n)] for r in range(n)]
        Q = G
        for _ in range(PROXIMAL_STEPS - 2):
            Q = [[G[r][s] + sp.dot(G[r], [row[s] for row in Q]) for s in range(n)] for r in range(n)]
        return [[Q[r][s] + 1.0 if r == s else Q[r][s] for s in range(n)] for r in range(n)]

    def solve_many(self, Q, b):
        """solve(b) with Q = step_sum()."""
        y = ldlt_solve(*self.factor, b)
        return [sp.dot(row, y) for row in Q]


class Delassus(DampedSolve):
    """J (contact rows), A = J M⁻¹Jᵀ and the factor of A + μ1, through half of M's solve: with
    M = Lᵀ D L and Z = L⁻ᵀJᵀ (a column non-zero only on its contact's tree ancestors), A = Zᵀ D⁻¹ Z
    and M⁻¹Jᵀλ = L⁻¹ D⁻¹ Z λ, one substitution for all contacts instead of one per row of J."""

    def __init__(self, m):
        self._parents = parents = fd.dof_parents(m.robot)
        self._L, inv_diag = fd.mass_matrix_factor(m)
        self.J = contact_rows(m, feet_jacobian(m))
        m.mark("contact: Delassus matrix J M⁻¹Jᵀ and its damped factor")
        A, self._Z, self._D_inv_Z = fd.half_solve_gram(self._L, inv_diag, parents, self.J, m.into_dof)
        super().__init__(A)

    def half_solves(self, m):
        """(Z, D⁻¹Z) over the robot's dofs, one column per row of J: J M⁻¹ = (D⁻¹Z)ᵀ L⁻ᵀ and
        M⁻¹Jᵀ = L⁻¹ D⁻¹Z, which contact_dynamics_derivatives' loops apply between M⁻¹'s halves."""
        return self._Z, self._D_inv_Z

    def feet_rows(self, m, values):
        """A per-foot quantity's rows (3 per foot) aligned with J's."""
        return contact_rows(m, values)

    def rows(self, values):
        """Values aligned with J's rows in the contact order of A (here the same)."""
        return list(values)

    @cached_property
    def Minv_Jt(self):
        """M⁻¹Jᵀ, one column per row of J (the derivatives need it whole)."""
        return [fd.ltdl_substitute(self._L, self._parents, column, range(len(column)))
                for column in self._D_inv_Z]

    def feet_forces(self, m, lam):
        """The feet's forces (3 per kept foot, zero off the contacts) of the contact forces λ."""
        forces = list(sp.zeros(3 * len(m.feet)))
        for c, foot in enumerate(m.contacts):
            k = m.feet.index(foot)
            forces[3 * k:3 * k + 3] = lam[3 * c:3 * c + 3]
        return forces

    def apply_Minv_Jt(self, lam):
        """M⁻¹Jᵀ λ = L⁻¹ (D⁻¹Z λ)."""
        n = len(self._parents)
        y = sp.zeros(n)
        for column, x in zip(self._D_inv_Z, lam):
            y = sp.vadd(y, sp.vscale(x, column))
        return fd.ltdl_substitute(self._L, self._parents, y, range(n))


class LaneDelassus(DampedSolve):
    """Delassus on the lane model (views/limb_lanes.py) with one contact foot per limb, the lane
    foot: J's three rows are lane rows (lane k: contact k), and Z = L⁻ᵀJᵀ keeps its lanes apart
    (contact k's column is non-zero on limb k and the trunk only, so no lane sum where a limb meets
    the trunk). A's diagonal 3 × 3 blocks are lane dot products over the limb's and the trunk's
    dofs; an off-diagonal block, two contacts on different limbs, sums over the trunk's dofs only,
    one lane against another: a lane dot product with the second operand's lanes rotated. The dense
    solve is scalar; λ returns to the lanes through one-hot lane constants."""

    def __init__(self, m, contact_lanes):
        self._lanes = contact_lanes  # lane of each contact, in the scene's contact order
        self._parents = parents = fd.dof_parents(m.robot)
        self._L, inv_diag = fd.mass_matrix_factor(m)
        self._root = m.robot.root_dofs
        self._into_root = m.into_root
        self.J = feet_jacobian(m)
        m.mark("contact: Delassus matrix J M⁻¹Jᵀ and its damped factor")
        self._Z = Z = [fd.ltdl_forward(self._L, parents, row) for row in self.J]
        self._D_inv_Z = [[z * d for z, d in zip(column, inv_diag)] for column in Z]
        # contact k's rows are lane k of the lane foot's (fd.lane_gram: a diagonal block sums over all
        # dofs, two contacts on different limbs over the trunk's)
        gram = fd.lane_gram(Z, self._D_inv_Z, range(self._root))
        rows = [(c, r) for c in range(len(contact_lanes)) for r in range(3)]
        A = [[None] * len(rows) for _ in rows]
        for i, (c, r) in enumerate(rows):
            for j, (d, s) in enumerate(rows[:i + 1]):
                A[i][j] = A[j][i] = fd.lane_gram_entry(gram, r, contact_lanes[c], s, contact_lanes[d])
        super().__init__(A)

    def feet_rows(self, m, values):
        return list(values)  # the lane foot's three rows

    def rows(self, values):
        """Lane values aligned with J's three rows as scalars in contact order."""
        return [ex.lane_get(values[r], k) for k in self._lanes for r in range(3)]

    def feet_forces(self, m, lam):
        """The lane foot's force: λ in the lanes."""
        return self._in_lanes(lam)

    def _in_lanes(self, lam):
        """λ's three rows back in the lanes through one-hot lane constants (zero in a lane without
        contact)."""
        in_lanes = []
        for r in range(3):
            x = ex.const(0.0)
            for c, k in enumerate(self._lanes):
                x = x + ex.lane_const([1.0 if lane == k else 0.0 for lane in range(ex.LANES)]) * lam[3 * c + r]
            in_lanes.append(x)
        return in_lanes

    def half_solves(self, m):
        """Delassus.half_solves over the full robot's dofs, in contact order: contact k's column is
        lane k of the lane columns (the other limbs' rows zero)."""
        places = [(0, k) for k in self._lanes]
        return m.place_rows(self._Z, places, 3), m.place_rows(self._D_inv_Z, places, 3)

    def apply_Minv_Jt(self, lam):
        """M⁻¹Jᵀ λ = L⁻¹ (D⁻¹Z λ): λ's rows back in the lanes, limb k's dofs take contact k's
        columns lane by lane, the trunk's dofs every contact's (the sum over the lanes)."""
        n = len(self._parents)
        in_lanes = self._in_lanes(lam)
        y = [sp.dot([column[i] for column in self._D_inv_Z], in_lanes) for i in range(n)]
        y = [self._into_root(x) if i < self._root else x for i, x in enumerate(y)]
        return fd.ltdl_substitute(self._L, self._parents, y, range(n))


def contact_dynamics(m, delassus=Delassus):
    """(a, λ): a₀ = M⁻¹(Sᵀτ − c − g), A λ = −(J a₀ + J̇v), a = a₀ + M⁻¹Jᵀλ; `delassus` builds the
    Delassus system from m (LaneDelassus on the lane model)."""
    a0 = fd.free_acceleration(m)
    delassus = delassus(m)
    m.mark("contact: J̇v of the contact points")
    bias = delassus.feet_rows(m, [x for foot in feet_bias_accelerations(m) for x in foot])
    m.mark("contact: forces and acceleration")
    lam = delassus.solve(delassus.rows([-(gamma + sp.dot(row, a0)) for gamma, row in zip(bias, delassus.J)]))
    return sp.vadd(a0, delassus.apply_Minv_Jt(lam)), lam


def impulse_dynamics(m, delassus=Delassus):
    """(v⁺, Λ): A Λ = −(1 + e) J v⁻, v⁺ = v⁻ + M⁻¹JᵀΛ, e = the restitution input."""
    delassus = delassus(m)
    m.mark("impact: impulses and velocity")
    scale = ex.const(1.0) + m.restitution
    v = m.tree_velocity
    impulse = delassus.solve(delassus.rows([-(scale * sp.dot(row, v)) for row in delassus.J]))
    return sp.vadd(v, delassus.apply_Minv_Jt(impulse)), impulse
