"""A straightforward numeric reference for the generator tests: dense 6×6 spatial algebra on plain
Python lists (no numpy), the textbook RNEA, mass matrix by unit accelerations, Gaussian
elimination, and the operational-space quantities from their closed forms (paper 001 Eqs. 10-15).
Deliberately independent of rbdcgen's structured algebra and of its algorithms' organisation."""

import math


# --- dense linear algebra ----------------------------------------------------------------------

def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(len(b))) for j in range(len(b[0]))]
            for i in range(len(a))]


def matvec(a, x):
    return [sum(a[i][k] * x[k] for k in range(len(x))) for i in range(len(a))]


def transpose(a):
    return [list(col) for col in zip(*a)]


def add(x, y):
    return [a + b for a, b in zip(x, y)]


def sub(x, y):
    return [a - b for a, b in zip(x, y)]


def identity(n):
    return [[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)]


def solve(a, b):
    """Gaussian elimination with partial pivoting; b is a list of right-hand-side columns."""
    n = len(a)
    m = [list(a[i]) + [col[i] for col in b] for i in range(n)]
    for k in range(n):
        p = max(range(k, n), key=lambda r: abs(m[r][k]))
        m[k], m[p] = m[p], m[k]
        for r in range(k + 1, n):
            factor = m[r][k] / m[k][k]
            for c in range(k, len(m[0])):
                m[r][c] -= factor * m[k][c]
    cols = []
    for j in range(len(b)):
        x = [0.0] * n
        for i in range(n - 1, -1, -1):
            x[i] = (m[i][n + j] - sum(m[i][c] * x[c] for c in range(i + 1, n))) / m[i][i]
        cols.append(x)
    return cols


def inverse(a):
    return transpose(solve(a, identity(len(a))))


def ltdl(a):
    """a = Lᵀ D L, L unit lower triangular: the textbook LDLᵀ of a with rows and columns reversed."""
    n = len(a)
    b = [[a[n - 1 - r][n - 1 - c] for c in range(n)] for r in range(n)]
    K, E = identity(n), [0.0] * n
    for j in range(n):
        E[j] = b[j][j] - sum(K[j][k] ** 2 * E[k] for k in range(j))
        for i in range(j + 1, n):
            K[i][j] = (b[i][j] - sum(K[i][k] * K[j][k] * E[k] for k in range(j))) / E[j]
    L = [[K[n - 1 - c][n - 1 - r] for c in range(n)] for r in range(n)]
    return L, E[::-1]


# --- spatial algebra (conventions.md) ------------------------------------------------------------

def skew(r):
    return [[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]]


def cross(a, b):
    return matvec(skew(a), b)


def blocks(tl, tr, bl, br):
    return [tl[i] + tr[i] for i in range(3)] + [bl[i] + br[i] for i in range(3)]


ZERO3 = [[0.0] * 3 for _ in range(3)]


def motion_transform(E, r):
    return blocks(E, ZERO3, [[-x for x in row] for row in matmul(E, skew(r))], E)


def crm(v):
    w, u = skew(v[:3]), skew(v[3:])
    return blocks(w, ZERO3, u, w)


def crf(v):
    return [[-x for x in row] for row in transpose(crm(v))]


def spatial_inertia(body):
    m, c = body.mass, list(body.com)
    C = skew(c)
    Ibar = [[body.inertia_com[i][j] + m * matmul(C, transpose(C))[i][j] for j in range(3)]
            for i in range(3)]
    mC = [[m * x for x in row] for row in C]
    return blocks(Ibar, mC, transpose(mC), [[m if i == j else 0.0 for j in range(3)]
                                            for i in range(3)])


def point_mass_inertia(mass, r):
    class Point:
        pass
    p = Point()
    p.mass, p.com, p.inertia_com = mass, r, ZERO3
    return spatial_inertia(p)


def axis_rotation(axis, q):
    """Active rotation about a unit axis (Rodrigues)."""
    n = math.sqrt(sum(a * a for a in axis))
    a = [x / n for x in axis]
    c, s = math.cos(q), math.sin(q)
    A = skew(a)
    AA = matmul(A, A)
    return [[(1.0 if i == j else 0.0) + s * A[i][j] + (1 - c) * AA[i][j] for j in range(3)]
            for i in range(3)]


def quaternion_rotation(w, x, y, z):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


# --- the robot ------------------------------------------------------------------------------------

class Reference:
    def __init__(self, robot, feet=None, gravity=None):
        self.robot = robot
        self.feet = list(robot.feet if feet is None else feet)
        self.gravity = list(robot.gravity if gravity is None else gravity)
        self.inertias = [spatial_inertia(b) for b in robot.bodies]

    def S(self, i):
        axis = list(self.robot.joints[i].axis)
        z = [0.0] * 3
        return axis + z if self.robot.joints[i].type == "revolute" else z + axis

    def X_up(self, q, i):
        j = self.robot.joints[i]
        X_T = motion_transform([list(r) for r in j.rotation], list(j.translation))
        qi = q[j.q_index]
        if j.type == "revolute":
            X_J = motion_transform(transpose(axis_rotation(j.axis, qi)), [0.0] * 3)
        else:
            X_J = motion_transform(identity(3), [qi * a for a in j.axis])
        return matmul(X_J, X_T)

    def base(self, q):
        if self.robot.floating_base:
            return quaternion_rotation(*q[3:7]), list(q[0:3])
        return identity(3), [0.0] * 3

    def frames(self, q):
        """(R_i body → world, p_i) from the dense X_0^i."""
        R0, p0 = self.base(q)
        X0 = [identity(6)]
        for i in range(1, self.robot.nb):
            X0.append(matmul(self.X_up(q, i), X0[self.robot.parent[i]]))
        out = []
        for X in X0:
            E = [row[:3] for row in X[:3]]
            rt = matmul(transpose(E), [[-x for x in row[:3]] for row in X[3:]])  # r̃
            r = [rt[2][1], rt[0][2], rt[1][0]]
            out.append((matmul(R0, transpose(E)), add(p0, matvec(R0, r))))
        return out

    def velocities(self, q, v):
        vel = [list(v[0:6]) if self.robot.floating_base else [0.0] * 6]
        for i in range(1, self.robot.nb):
            j = self.robot.joints[i]
            vel.append(add(matvec(self.X_up(q, i), vel[self.robot.parent[i]]),
                           [v[j.v_index] * s for s in self.S(i)]))
        return vel

    def rnea(self, q, v, a, gravity, foot_forces=None, extra_inertia=None):
        """Σ M a + c + g − τ_e. extra_inertia[i]: added inertia moving with body i that feels
        neither gravity nor velocity products (the ground point masses of paper 001 Table 2)."""
        robot = self.robot
        R0, _ = self.base(q)
        g0 = matvec(transpose(R0), gravity)
        vel = self.velocities(q, v)
        if robot.floating_base:
            w, u = v[0:3], v[3:6]
            acc = [list(a[0:3]) + sub(a[3:6], cross(w, u))]
        else:
            acc = [[0.0] * 6]
        acc[0] = sub(acc[0], [0.0] * 3 + g0)
        for i in range(1, robot.nb):
            j = robot.joints[i]
            Sq = [v[j.v_index] * s for s in self.S(i)]
            acc.append(add(add(matvec(self.X_up(q, i), acc[robot.parent[i]]),
                               matvec(crm(vel[i]), Sq)), [a[j.v_index] * s for s in self.S(i)]))
        frames = self.frames(q)
        forces = []
        for i in range(robot.nb):
            I = self.inertias[i]
            f = add(matvec(I, acc[i]), matvec(crf(vel[i]), matvec(I, vel[i])))
            if extra_inertia and extra_inertia[i] is not None:
                g_i = matvec(transpose(frames[i][0]), gravity)
                f = add(f, matvec(extra_inertia[i], add(acc[i], [0.0] * 3 + g_i)))
            forces.append(f)
        if foot_forces is not None:
            for k, foot in enumerate(self.feet):
                F = matvec(transpose(frames[foot.body][0]), foot_forces[k])
                forces[foot.body] = sub(forces[foot.body], cross(foot.offset, F) + F)
        tau = [0.0] * robot.nv
        for i in range(robot.nb - 1, 0, -1):
            j = robot.joints[i]
            tau[j.v_index] = sum(s * f for s, f in zip(self.S(i), forces[i]))
            p = robot.parent[i]
            forces[p] = add(forces[p], matvec(transpose(self.X_up(q, i)), forces[i]))
        if robot.floating_base:
            tau[0:6] = forces[0]
        return tau

    # --- quantities -------------------------------------------------------------------------
    def inverse_dynamics(self, q, v, a):
        return self.rnea(q, v, a, self.gravity)

    def mass_matrix(self, q, extra_inertia=None):
        n = self.robot.nv
        zero = [0.0] * n
        cols = [self.rnea(q, zero, [1.0 if k == c else 0.0 for k in range(n)], [0.0] * 3,
                          extra_inertia=extra_inertia) for c in range(n)]
        return transpose(cols)

    def quadratic_velocity_terms(self, q, v):
        return self.rnea(q, v, [0.0] * self.robot.nv, [0.0] * 3)

    def gravity_terms(self, q):
        zero = [0.0] * self.robot.nv
        return self.rnea(q, zero, zero, self.gravity)

    def feet_positions(self, q):
        frames = self.frames(q)
        return [add(frames[f.body][1], matvec(frames[f.body][0], list(f.offset)))
                for f in self.feet]

    def feet_velocities(self, q, v):
        frames = self.frames(q)
        vel = self.velocities(q, v)
        return [matvec(frames[f.body][0], add(vel[f.body][3:], cross(vel[f.body][:3], f.offset)))
                for f in self.feet]

    def feet_jacobian(self, q):
        n = self.robot.nv
        cols = []
        for c in range(n):
            vel = self.feet_velocities(q, [1.0 if k == c else 0.0 for k in range(n)])
            cols.append([x for foot in vel for x in foot])
        return transpose(cols)

    def feet_force_terms(self, q, forces):
        J = self.feet_jacobian(q)
        flat = [x for f in forces for x in f]
        return matvec(transpose(J), flat)

    def forward_dynamics(self, q, v, tau, forces):
        root = self.robot.root_dofs
        bias = self.rnea(q, v, [0.0] * self.robot.nv, self.gravity, foot_forces=forces)
        rhs = [-b for b in bias[:root]] + [t - b for t, b in zip(tau, bias[root:])]
        return solve(self.mass_matrix(q), [rhs])[0]

    def _osc(self, H, bias):
        """Λ = (J_t H⁻¹ J_tᵀ)⁻¹, J̄ᵀ = Λ J_t H⁻¹ (joint columns), b = J̄ᵀ bias (Eqs. 10-15 with
        J_t = [1 0] and J̇_t q̇ = 0 in these coordinates)."""
        Hinv = inverse(H)
        Lam = inverse([row[:6] for row in Hinv[:6]])
        JbarT_full = matmul(Lam, Hinv[:6])
        return Lam, [row[6:] for row in JbarT_full], matvec(JbarT_full, bias)

    def osc_open_chain(self, q, v, forces):
        bias = self.rnea(q, v, [0.0] * self.robot.nv, self.gravity, foot_forces=forces)
        return self._osc(self.mass_matrix(q), bias)

    def osc_closed_chain(self, q, v, ground_mass, contacts=None):
        """The big-ground-inertia system: a point mass ground_mass at each contact foot."""
        extra = [None] * self.robot.nb
        for foot in (self.feet if contacts is None else contacts):
            pm = point_mass_inertia(ground_mass, list(foot.offset))
            extra[foot.body] = pm if extra[foot.body] is None else [
                add(r1, r2) for r1, r2 in zip(extra[foot.body], pm)]
        bias = self.rnea(q, v, [0.0] * self.robot.nv, self.gravity, extra_inertia=extra)
        return self._osc(self.mass_matrix(q, extra_inertia=extra), bias)


def constrained_osc(ref, q):
    """Λ̃_t and J̃_tᵀ of the exactly constrained system (paper 001 Eqs. 20-24), all feet pinned."""
    H = ref.mass_matrix(q)
    Hinv = inverse(H)
    Jc = ref.feet_jacobian(q)
    Lam_c = inverse(matmul(matmul(Jc, Hinv), transpose(Jc)))
    JbarT_c = matmul(matmul(Lam_c, Jc), Hinv)                       # J̄_cᵀ
    n = len(H)
    NcT = [[(1.0 if i == j else 0.0) - x for j, x in enumerate(row)]
           for i, row in enumerate(matmul(transpose(Jc), JbarT_c))]  # N_cᵀ = 1 − J_cᵀ J̄_cᵀ
    HinvNcT = matmul(Hinv, NcT)
    Lam = inverse([row[:6] for row in HinvNcT[:6]])
    JtildeT = matmul(Lam, HinvNcT[:6])
    return Lam, [row[6:] for row in JtildeT[:6]] if n > 6 else []
