"""Spatial algebra over symbolic scalars (docs/conventions.md, runtime/include/rbdc/spatial.hpp).

Vectors are tuples of `Expr`: 3-vectors, 6-vectors ordered (angular; linear), 3×3 and 6×6 matrices
as tuples of rows. Transforms and inertias keep their structure (rotation + translation; mass,
first moment, rotational inertia) instead of dense 6×6 matrices, so applying them costs far
fewer operations even before folding removes the zeros of constant parameters.
"""

from __future__ import annotations

import functools
import math
import sys

from . import expr as ex


def vec(values):
    return tuple(ex.lift(x) for x in values)


def mat(rows):
    return tuple(vec(row) for row in rows)


def zeros(n):
    return tuple(ex.const(0.0) for _ in range(n))


def identity3():
    return mat([[1, 0, 0], [0, 1, 0], [0, 0, 1]])


def vadd(a, b):
    return tuple(x + y for x, y in zip(a, b))


def vsub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def vscale(s, a):
    return tuple(s * x for x in a)


def vneg(a):
    return tuple(-x for x in a)


def pack_halves(low, high):
    """Vectors low and high in one vector of lane values: low's lanes 0-1, high's 2-3 (a limb pair's
    spare lanes, views/limb_lanes.spare_lanes)."""
    return tuple(ex.pack_lane_halves(x, y) for x, y in zip(low, high))


def swap_halves(a):
    return tuple(ex.swap_lane_halves(x) for x in a)


def dot(a, b):
    total = ex.const(0.0)
    for x, y in zip(a, b):
        total = total + x * y
    return total


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def matvec(m, a):
    return tuple(dot(row, a) for row in m)


def transpose(m):
    return tuple(tuple(row[j] for row in m) for j in range(len(m[0])))


def matmul(a, b):
    bt = transpose(b)
    return tuple(tuple(dot(row, col) for col in bt) for row in a)


def mat_tmatvec(m, a):
    """mᵀ a without building the transpose."""
    return matvec(transpose(m), a)


def skew(r):
    """r̃ with r̃ x = r × x (paper 000 App. A)."""
    z = ex.const(0.0)
    return ((z, -r[2], r[1]), (r[2], z, -r[0]), (-r[1], r[0], z))


def symmetric(m):
    """The symmetric matrix built from the upper triangle of m (the lower one is then dead)."""
    n = len(m)
    return tuple(tuple(m[min(i, j)][max(i, j)] for j in range(n)) for i in range(n))


# --- motion and force vectors ----------------------------------------------------------------

def ang(v):
    return v[:3]


def lin(v):
    return v[3:]


def crm(v, m):
    """v × m, the motion cross product (twist product "*" of paper 000 App. A)."""
    w, u = ang(v), lin(v)
    return cross(w, ang(m)) + vadd(cross(w, lin(m)), cross(u, ang(m)))


def crf(v, f):
    """v ×* f, the force cross product (wrench product "⊗" of paper 000 App. A)."""
    w, u = ang(v), lin(v)
    return vadd(cross(w, ang(f)), cross(u, lin(f))) + cross(w, lin(f))


# --- rotations --------------------------------------------------------------------------------

def unit_axis_index(axis):
    """Index k when axis = ±e_k exactly, else None."""
    nonzero = [k for k, a in enumerate(axis) if a != 0.0]
    if len(nonzero) == 1 and abs(axis[nonzero[0]]) == 1.0:
        return nonzero[0]
    return None


def coordinate_rotation(axis, c, s):
    """E = rot(axis, q)ᵀ from c = cos q, s = sin q: coordinates in the rotated frame.
    For a coordinate axis the entries are built directly, so the 1 on the axis is exact."""
    a = [float(x) for x in axis]
    norm = math.sqrt(sum(x * x for x in a))
    a = [x / norm for x in a]
    k = unit_axis_index(a)
    one, zero = ex.const(1.0), ex.const(0.0)
    if k is not None:
        sign = a[k]
        i, j = (k + 1) % 3, (k + 2) % 3
        m = [[zero] * 3 for _ in range(3)]
        m[k][k] = one
        m[i][i], m[j][j] = c, c
        # Rᵀ of a rotation about ±e_k: the (i, j) entry is +s·sign, (j, i) is −s·sign.
        m[i][j] = s * sign
        m[j][i] = -(s * sign)
        return tuple(tuple(row) for row in m)
    t = one - c
    rows = []
    for r in range(3):
        row = []
        for col in range(3):
            entry = t * (a[r] * a[col])
            if r == col:
                entry = entry + c
            else:
                # −s·[a]× entry (r, col): [a]×[r][col] = −ε_{r col k} a_k
                eps = {(0, 1): -a[2], (0, 2): a[1], (1, 0): a[2], (1, 2): -a[0],
                       (2, 0): -a[1], (2, 1): a[0]}[(r, col)]
                entry = entry - s * eps
            row.append(entry)
        rows.append(tuple(row))
    return tuple(rows)


def quaternion_rotation(w, x, y, z):
    """Active rotation R (trunk → world) of a unit quaternion (w, x, y, z)."""
    x2, y2, z2 = x + x, y + y, z + z
    xx, yy, zz = x * x2, y * y2, z * z2
    xy, xz, yz = x * y2, x * z2, y * z2
    wx, wy, wz = w * x2, w * y2, w * z2
    one = ex.const(1.0)
    return ((one - (yy + zz), xy - wz, xz + wy),
            (xy + wz, one - (xx + zz), yz - wx),
            (xz - wy, yz + wx, one - (xx + yy)))


_SNAP_TOLERANCE = 4 * 2.220446049250313e-16


def _snap(x):
    x = float(x)
    if abs(x) <= _SNAP_TOLERANCE:
        return 0.0
    if abs(abs(x) - 1.0) <= _SNAP_TOLERANCE:
        return math.copysign(1.0, x)
    return x


# A sum within this many ulp of its largest term is a cancellation that means zero: a left and a right
# limb's inertia pieces meeting in the trunk (views/regrouped.py), a placement slid by its own length
# (views/origins.py). Left as 1e-17, it would cost a multiplication each.
ROUND_OFF_ULPS = 8


def snapped_sum(values):
    """The floats' sum, or 0.0 where it is within ROUND_OFF_ULPS ulp of the largest of them."""
    total = sum(values)
    return 0.0 if abs(total) <= ROUND_OFF_ULPS * sys.float_info.epsilon * max(map(abs, values)) else total


def snap_rotation(rows):
    """A constant rotation with entries within 4 ulp of 0 or ±1 made exact. URDF angles such as π
    leave entries like 1.2e-16 that would cost a multiply each; the change is below round-off."""
    return tuple(tuple(_snap(x) for x in row) for row in rows)


def snap_axis(axis):
    """A unit joint axis with the same snapping, so (1e-17, 0, 1) is recognised as e_z."""
    return tuple(_snap(x) for x in axis)


def snap_vector(vector):
    """Any constant vector with the same snapping: a point turned by views/turns.py, whose zero
    entries come out as 1e-17."""
    return tuple(_snap(x) for x in vector)


# --- transforms -------------------------------------------------------------------------------

class Transform:
    """X_A^B = [E 0; −E r̃ E] (paper 000 Eq. 5): E rotates A → B coordinates, r is the origin of B
    in A coordinates. `E` may be None for a pure translation and `r` None for a pure rotation;
    the structure then costs nothing."""

    __slots__ = ("E", "r")

    def __init__(self, E=None, r=None):
        self.E = E
        self.r = r

    def rotate(self, a):
        return a if self.E is None else matvec(self.E, a)

    def rotate_back(self, a):
        return a if self.E is None else mat_tmatvec(self.E, a)

    def motion(self, m):
        """X m = (E ω, E (v − r × ω))."""
        w, u = ang(m), lin(m)
        if self.r is not None:
            u = vsub(u, cross(self.r, w))
        return self.rotate(w) + self.rotate(u)

    def force_T(self, f):
        """Xᵀ f = (Eᵀ n + r × Eᵀ f, Eᵀ f): a force in B coordinates back to A (Eq. 8)."""
        n, u = self.rotate_back(ang(f)), self.rotate_back(lin(f))
        if self.r is not None:
            n = vadd(n, cross(self.r, u))
        return n + u

    def point(self, p):
        """Coordinates in B of a point given in A coordinates: E (p − r)."""
        return self.rotate(p if self.r is None else vsub(p, self.r))

    def then(self, outer):
        """outer · self as one Transform (A → B → C): E = E_o E, r = r + Eᵀ r_o."""
        if outer.E is None:
            E = self.E
        else:
            E = outer.E if self.E is None else matmul(outer.E, self.E)
        if outer.r is None:
            r = self.r
        else:
            back = self.rotate_back(outer.r)
            r = back if self.r is None else vadd(self.r, back)
        return Transform(E, r)


class Chain:
    """A product of transforms applied one after the other (e.g. X_J · X_T, Eq. 11), so each
    factor keeps its own sparsity."""

    __slots__ = ("factors",)

    def __init__(self, *factors):
        self.factors = factors  # innermost (applied first) first

    def motion(self, m):
        for x in self.factors:
            m = x.motion(m)
        return m

    def force_T(self, f):
        for x in reversed(self.factors):
            f = x.force_T(f)
        return f

    def congruence(self, inertia):
        """Xᵀ I X of a spatial inertia, factor by factor."""
        for x in reversed(self.factors):
            inertia = inertia.congruence(x)
        return inertia

    def congruence6(self, m):
        """Xᵀ M X for a symmetric 6×6 M, factor by factor or with the factors merged into one
        transform, whichever takes fewer operations: merged, a tilted placement and the joint's
        rotation become one dense rotation of M's blocks instead of a sparse and a dense one (a
        100-body chain of tilted placements: 8 % fewer operations in its articulated-body
        algorithm); always merged, Talos's took 1.6 % more."""
        given = [e for row in m for e in row] + [e for x in self.factors for e in _entries(x)]
        shape = (tuple((x.E is None, x.r is None) for x in self.factors), _shape(given))
        merge = _MERGE_CHOICE.get(shape)
        separate = None
        if merge is not True:
            separate = m
            for x in reversed(self.factors):
                separate = congruence6(x, separate)
        merged = None if merge is False else congruence6(functools.reduce(Transform.then, self.factors), m)
        if merge is None:
            merge = _operations(merged, given) < _operations(separate, given)
            _MERGE_CHOICE[shape] = merge
        return merged if merge else separate


# Chain.congruence6's choice by the shape of its operands (_shape): the same shape folds the same way
# and takes the same operations, so each shape is decided once (a 200-body chain's articulated-body
# algorithm and OSC recursions built both forms for 600 bodies, a tenth of their generation).
_MERGE_CHOICE = {}


def _shape(given):
    """What folding sees of the expressions `given`: constants by value; other nodes by which of them
    are the same node, their operation, a lane constant's lanes, and a first operand's constant."""
    first_seen = {}
    shape = []
    for e in given:
        if e.op == "const":
            shape.append(e.value)
            continue
        first = e.args[0] if e.args else None
        shape.append((first_seen.setdefault(e.id, len(first_seen)), e.op, e.lane, ex.constant_lanes(e),
                      first.value if first is not None and first.op == "const" else None))
    return tuple(shape)


def _entries(x):
    """A transform's expressions: E's entries and r's."""
    return [e for row in (x.E or ()) for e in row] + list(x.r or ())


def _operations(rows, given):
    """The operations computing the matrix `rows` from the expressions `given`."""
    stop = {e.id for e in given}
    seen, stack, count = set(), [e for row in rows for e in row], 0
    while stack:
        node = stack.pop()
        if node.id in seen or node.id in stop:
            continue
        seen.add(node.id)
        count += node.op not in ("const", "sym")
        stack.extend(node.args)
    return count


def congruence6(x, m):
    """Xᵀ M X for a symmetric 6×6 M (articulated inertias) and X = (E, r), by 3×3 blocks
    M = [A B; Bᵀ C]: rotated, A' = Eᵀ A E, B' = Eᵀ B E, C' = Eᵀ C E; then shifted by X's
    translation [1 0; −r̃ 1], B'' = B' + r̃ C' and A'' = A' + (r̃ B'ᵀ)ᵀ + r̃ B''ᵀ. The symmetric
    blocks are computed on one triangle (column by column through force_T, a 100-body chain's
    articulated-body algorithm took 6 % more operations)."""
    A = tuple(row[:3] for row in m[:3])
    B = tuple(row[3:] for row in m[:3])
    C = tuple(row[3:] for row in m[3:])
    if x.E is not None:
        A = _rotated_symmetric(x.E, A)
        B = matmul(transpose(x.E), matmul(B, x.E))
        C = _rotated_symmetric(x.E, C)
    if x.r is not None:
        shift = skew(x.r)
        B_shifted = tuple(vadd(row, shifted) for row, shifted in zip(B, matmul(shift, C)))
        A = symmetric_of(3, lambda j, i: A[i][j] + dot(shift[j], B[i]) + dot(shift[i], B_shifted[j]))
        B = B_shifted
    return tuple(tuple(A[i]) + tuple(B[i]) for i in range(3)) + tuple(
        tuple(B[j][i] for j in range(3)) + tuple(C[i]) for i in range(3))


def symmetric_of(n, entry):
    """The symmetric n × n matrix (rows) with entry(r, c) for r ≥ c, mirrored above."""
    rows = [[None] * n for _ in range(n)]
    for r in range(n):
        for c in range(r + 1):
            rows[r][c] = rows[c][r] = entry(r, c)
    return tuple(map(tuple, rows))


def _rotated_symmetric(E, S):
    """Eᵀ S E for a symmetric S, on one triangle."""
    SE = matmul(S, E)
    return symmetric_of(3, lambda j, i: sum((E[k][i] * SE[k][j] for k in range(1, 3)), E[0][i] * SE[0][j]))


def matvec6(m, a):
    return matvec(m, a)


def mat6_add(a, b):
    return tuple(vadd(ra, rb) for ra, rb in zip(a, b))


def outer(a, b):
    return tuple(tuple(x * y for y in b) for x in a)


# --- spatial inertia ---------------------------------------------------------------------------

def inertia_at_origin(body):
    """A body's rotational inertia about its origin, in floats: Ī = I_c + m (|c|² 1 − c cᵀ)."""
    c, m = body.com, body.mass
    cc = sum(x * x for x in c)
    return [[body.inertia_com[i][j] + m * ((cc if i == j else 0.0) - c[i] * c[j]) for j in range(3)]
            for i in range(3)]


class Inertia:
    """Spatial inertia at a frame origin from mass m, first moment h = m c and rotational inertia
    Ī about the origin: I = [Ī h̃; h̃ᵀ m1] (conventions.md, paper 000 Eq. 21 generalised)."""

    __slots__ = ("m", "h", "Ibar")

    def __init__(self, m, h, Ibar):
        self.m, self.h, self.Ibar = m, h, Ibar

    @staticmethod
    def of(m, h, Ibar):
        """From floats: mass, first moment, rotational inertia about the origin."""
        return Inertia(ex.const(m), vec(h), symmetric(mat(Ibar)))

    def apply(self, v):
        """I v = (Ī ω + h × v_O, m v_O − h × ω)."""
        w, u = ang(v), lin(v)
        return (vadd(matvec(self.Ibar, w), cross(self.h, u))
                + vsub(vscale(self.m, u), cross(self.h, w)))

    def __add__(self, other):
        return Inertia(self.m + other.m, vadd(self.h, other.h),
                       symmetric(tuple(vadd(a, b) for a, b in zip(self.Ibar, other.Ibar))))

    def congruence(self, x):
        """Xᵀ I X for X = (E, r): the inertia expressed in the A coordinates of X_A^B.
        y = Eᵀ h, h' = y + m r, Ī' = Eᵀ Ī E − r̃ ỹ − h̃' r̃ (only the upper triangle computed)."""
        h, ibar = self.h, self.Ibar
        if x.E is not None:
            h = mat_tmatvec(x.E, h)
            ibar = symmetric(matmul(transpose(x.E), matmul(ibar, x.E)))
        if x.r is None:
            return Inertia(self.m, h, ibar)
        r = x.r
        h_new = vadd(h, vscale(self.m, r))
        shift = mat6_add(matmul(skew(r), skew(h)), matmul(skew(h_new), skew(r)))
        ibar = symmetric(tuple(vsub(a, b) for a, b in zip(ibar, shift)))
        return Inertia(self.m, h_new, ibar)

    def dense(self):
        """The 6×6 matrix (for the articulated-body recursions)."""
        h = skew(self.h)
        z = ex.const(0.0)
        m = self.m
        top = [tuple(self.Ibar[i]) + tuple(h[i]) for i in range(3)]
        bottom = [tuple(h[j][i] for j in range(3)) + tuple(m if i == j else z for j in range(3))
                  for i in range(3)]
        return tuple(top + bottom)
