"""Operation counts: of the emitted DAG (count_ops) and of the generic dense-6×6 algorithm the
runtime runs (generic_ops, counted analytically), so the saving from folding is visible.

Both return dict(mul, add, div, sqrt, trig, neg, total); `add` includes subtractions, `trig` sin
and cos, `total` is the sum of all of them (every operation counts one)."""

from __future__ import annotations

from . import expr as ex

_KIND = {"mul": "mul", "add": "add", "sub": "add", "div": "div", "sqrt": "sqrt",
         "sin": "trig", "cos": "trig", "neg": "neg"}
KINDS = ("mul", "add", "div", "sqrt", "trig", "neg")


def _result(counts):
    out = {k: counts.get(k, 0) for k in KINDS}
    out["total"] = sum(out.values())
    return out


def count_ops(fn):
    """Operations of the live DAG of `fn` after folding, CSE and DCE (what emit_body prints), and of
    its looped solve if it has one. A lane operation counts once per lane (ex.LANES), the sum over
    the lanes as LANES − 1 additions, a lane joint angle's sin or cos once per distinct lane (a
    pair's 2: emit computes only those) and its offset once per distinct lane where it is not 0."""
    counts = {}
    nodes = ex.reachable(fn.output_exprs())
    lane_angles = {n.args[0].id: angle for n in nodes if n.op in ("sin", "cos") and n.lane
                   and (angle := ex.joint_angle(n.args[0])) is not None}
    for node in nodes:
        kind = "add" if node.op == "lane_sum" else _KIND.get(node.op)
        if kind is not None:
            times = ex.LANES - 1 if node.op == "lane_sum" else ex.LANES if node.lane else 1
            if kind == "trig" and node.args[0].id in lane_angles:
                times = fn.lanes.distinct_lanes(*lane_angles[node.args[0].id][0].value)
            elif node.id in lane_angles:  # an offset added to each distinct lane's angle where not 0
                symbol, offset = lane_angles[node.id]
                times = sum(x != 0.0 for x in ex.constant_lanes(offset)[:fn.lanes.distinct_lanes(*symbol.value)])
            counts[kind] = counts.get(kind, 0) + times
    if fn.solve is not None:  # the loop that solves the traced terms (passes/looped_solve.py)
        for kind, n in fn.solve.operations().items():
            counts[kind] = counts.get(kind, 0) + n
    return _result(counts)


class _Tally:
    """Analytic count of dense 6×6 spatial arithmetic, as in runtime/include/rbdc/spatial.hpp."""

    def __init__(self):
        self.c = {k: 0 for k in KINDS}

    def add(self, mul=0, add=0, div=0, sqrt=0, trig=0, times=1):
        for key, value in (("mul", mul), ("add", add), ("div", div), ("sqrt", sqrt),
                           ("trig", trig)):
            self.c[key] += value * times

    # Dense primitives.
    def mv6(self, times=1):        # 6×6 · 6-vector
        self.add(36, 30, times=times)

    def mm6(self, times=1):        # 6×6 · 6×6
        self.add(216, 180, times=times)

    def v6(self, times=1):         # 6-vector sum
        self.add(0, 6, times=times)

    def mv3(self, times=1):        # 3×3 · 3-vector
        self.add(9, 6, times=times)

    def mm3(self, times=1):        # 3×3 · 3×3
        self.add(27, 18, times=times)

    def dot6(self, times=1):       # S_iᵀ f
        self.add(6, 5, times=times)

    def scale6(self, times=1):     # S_i q̇_i
        self.add(6, 0, times=times)

    # Algorithm building blocks.
    def joint_transforms(self, robot):
        """X_up = X_J(q) X_T per joint: axis-angle rotation (sin, cos, Rodrigues) and one 6×6
        product (Eq. 11)."""
        self.add(13, 9, trig=2, times=robot.n_joints)
        self.mm6(robot.n_joints)

    def base_rotation(self, robot):
        if robot.floating_base:
            self.add(12, 12)       # unit quaternion → rotation matrix

    def world_transforms(self, robot):
        """X_W^0 (Eq. 14: E r̃ product) and X_W^i = X_up X_W^λ(i) (Eq. 15)."""
        self.base_rotation(robot)
        self.mm3()
        self.mm6(robot.n_joints)

    def velocities(self, robot):
        """Alg. 1 line 7: v_i = X_up v_λ + S q̇."""
        self.mv6(robot.n_joints)
        self.scale6(robot.n_joints)
        self.v6(robot.n_joints)

    def inward(self, robot):
        """Eqs. 22-23: c_i = S_iᵀ f_i, f_λ += X_upᵀ f_i."""
        self.dot6(robot.n_joints)
        self.mv6(robot.n_joints)
        self.v6(robot.n_joints)

    def rnea(self, robot, velocity, acceleration):
        """Outward accelerations and forces of Alg. 2/3 (and the full RNEA), dense."""
        nj, nb = robot.n_joints, robot.nb
        self.mv6(nj)                               # X_up a_λ
        if velocity:
            self.add(6, 3)                         # a₀ bias ω̃₀ v₀
            self.scale6(nj)
            self.mv6(nj)                           # v_i × S q̇ (crm dense)
            self.v6(nj)
            self.mv6(2 * nb)                       # I v, v ×* (I v)
            self.v6(nb)
        if acceleration:
            self.scale6(nj)
            self.v6(nj)
        self.mv6(nb)                               # I a
        self.mv3()                                 # R_W^0 g
        self.inward(robot)

    def crba(self, robot):
        """Alg. 5: I_cλ += X_upᵀ I_c X_up, F = I_c S, H_ij along κ, X_0^i for the root block."""
        self.mm6(2 * robot.n_joints)
        self.add(0, 36, times=robot.n_joints)
        self.mv6(robot.n_joints)
        self.dot6(robot.n_joints)
        for i in range(1, robot.nb):
            depth = len(robot.support[i]) - 1
            self.mv6(depth)
            self.dot6(depth)
            if robot.floating_base:
                self.mv6()                         # X_upᵀ F up to the trunk
        self.mm6(sum(1 for i in range(1, robot.nb) if robot.parent[i] != 0))  # X_0^i

    def cholesky_factor(self, n):
        """Dense LLᵀ (n³/6)."""
        cubic = n * n * n // 6
        self.add(cubic, cubic, div=n * (n - 1) // 2, sqrt=n)

    def cholesky_solve(self, n):
        """Dense LLᵀ and two triangular solves (n² each)."""
        self.cholesky_factor(n)
        self.add(n * n, n * n, div=2 * n)

    def delassus(self, robot, nf, nc):
        """The runtime's contact solve (runtime/src/contact_dynamics.cpp): the feet Jacobian, M⁻¹Jᵀ
        by 3·nc solves with the factor of M, A = J M⁻¹Jᵀ, LLᵀ of A + μ1, five proximal steps
        (A x and two triangular solves each) and M⁻¹Jᵀ λ."""
        n, m = robot.nv, 3 * nc
        self.world_transforms(robot)
        for foot in robot.feet[:nf]:
            self.mm6(1 + len(robot.support[foot.body]))
            self.mv6(len(robot.support[foot.body]))
        self.add(n * n, n * n, div=2 * n, times=m)
        self.add(m * m * n, m * m * n)
        self.cholesky_factor(m)
        self.add(2 * m * m, 2 * m * m, div=2 * m, times=5)   # kContactProximalSteps
        self.add(n * m, n * m)

    def foot_wrenches(self, robot, nf):
        """Alg. 4 outward loop: world force → body wrench via X̄ (rotation + 6×6 product)."""
        self.mv3(nf)
        self.mv6(nf)

    def osc(self, robot, nf, closed):
        """Paper 001 Table 1 (and Table 2) with dense 6×6 operations."""
        nj, nb = robot.n_joints, robot.nb
        self.velocities(robot)
        self.scale6(nj)
        self.mv6(nj)                               # ζ_i = v_i × S q̇
        self.mv6(2 * nb)                           # β = v ×* I v
        if closed:
            self.mm6(4 * nf)                       # K_c, Lᵀ_c, Xᵀ Lᵀ I_c X
            self.mv6(3 * nf)
        else:
            self.foot_wrenches(robot, nf)
        for i in range(nb - 1, 0, -1):
            self.mv6()                             # U = I^A S
            self.dot6()
            self.add(0, 0, div=1)                  # D = (Sᵀ U)⁻¹
            self.add(36, 0)                        # K = S D Sᵀ
            self.mm6()                             # Lᵀ = 1 − I^A K
            self.add(0, 6)
            self.mm6(3)                            # Xᵀ Lᵀ I^A X
            self.add(0, 36)
            self.mv6(3)                            # Xᵀ Lᵀ (β + I ζ)
            self.v6(2)
            self.mv6()                             # B_λi = −Xᵀ U D
            self.add(6, 0)
            self.mv6(2 * 6 * (len(robot.subtree[i]) - 1))   # B_λk = Xᵀ Lᵀ B_ik, 6 columns each
        self.mv3()
        self.mv6()                                 # b = β − I (a_g + (0, ω × v))
        self.add(6, 9)


def generic_ops(robot, scene, name):
    """Operation count of the runtime's generic dense algorithm for quantity `name` (a traced
    function's `computes`: a lane function counts as its scalar namesake)."""
    if name in _DERIVATIVE_DIRECTIONS:
        return _generic_derivative_ops(robot, scene, name)
    if name in _COMBINED_PARTS:  # the runtime's separate calls for the same outputs
        parts = [generic_ops(robot, scene, part) for part in _COMBINED_PARTS[name]]
        return _result({k: sum(p[k] for p in parts) for k in KINDS})
    nf = len(scene.feet_for(robot))
    nv = robot.nv
    t = _Tally()
    t.joint_transforms(robot)
    if name == "feet_positions":
        t.world_transforms(robot)
        t.mm6(nf)                                  # X_W^fk = X_i^fk X_W^i (Eq. 17)
        t.mm3(nf)                                  # Eq. 18
    elif name == "feet_velocities":
        t.world_transforms(robot)
        t.velocities(robot)
        t.mv6(nf)
        t.mv3(nf)
    elif name == "feet_jacobian":
        t.world_transforms(robot)
        for foot in scene.feet_for(robot):
            t.mm6()                                # X_W^fk
            depth = len(robot.support[foot.body])
            t.mm6(depth)                           # X_j^fk along κ (Alg. 6)
            t.mv6(depth)
            t.mv3(depth)
            if robot.floating_base:
                t.mm6()
                t.mv3(6)
    elif name == "quadratic_velocity_terms":
        t.velocities(robot)
        t.rnea(robot, True, False)
    elif name == "gravity_terms":
        t.base_rotation(robot)
        t.rnea(robot, False, False)
    elif name == "feet_force_terms":
        t.world_transforms(robot)
        t.foot_wrenches(robot, nf)
        t.inward(robot)
    elif name in ("inverse_dynamics", "bias"):   # the runtime's bias is inverse dynamics at a = 0
        t.base_rotation(robot)
        t.velocities(robot)
        t.rnea(robot, True, True)
    elif name in ("mass_matrix", "mass_matrix_lower"):  # the runtime computes all of M
        t.crba(robot)
    elif name == "mass_matrix_factor":
        t.crba(robot)
        t.cholesky_factor(nv)
    elif name == "forward_dynamics":
        t.base_rotation(robot)
        t.crba(robot)
        t.velocities(robot)
        t.rnea(robot, True, False)
        t.world_transforms(robot)
        t.foot_wrenches(robot, nf)
        t.cholesky_solve(nv)
    elif name == "contact_dynamics":
        t = _Tally()                               # the forward dynamics' count has the joint transforms
        fd = generic_ops(robot, scene, "forward_dynamics")
        t.add(**{k: fd[k] for k in ("mul", "add", "div", "sqrt", "trig")})
        t.velocities(robot)
        t.mv6(2 * (robot.nb - 1))                  # J̇v: the velocity-product accelerations
        t.delassus(robot, nf, len(scene.contacts_for(robot)))
    elif name == "impulse_dynamics":
        t.crba(robot)
        t.cholesky_factor(nv)
        t.delassus(robot, nf, len(scene.contacts_for(robot)))
    elif name in ("osc_open_chain", "osc_closed_chain"):
        t.base_rotation(robot)
        t.osc(robot, nf if name == "osc_open_chain" else len(scene.contacts_for(robot)),
              closed=name == "osc_closed_chain")
    elif name in _WHOLE_BODY_GENERIC:
        _WHOLE_BODY_GENERIC[name](t, robot, scene)
    else:
        raise KeyError("unknown function '%s'" % name)
    return _result(t.c)


def _frame_jacobian_ops(t, robot, bodies):
    """Per frame or point on body i: X_j^i S_j along κ(i) (Alg. 6), X_i^F J (6 × nv) and its rotation."""
    for body in bodies:
        depth = len(robot.support[body])
        t.mm6(depth)
        t.mv6(depth + robot.nv)
        t.mv3(2 * robot.nv)
        if robot.floating_base:
            t.mm6()


def _bias_pass_ops(t, robot, n_points):
    """Velocities, the a = 0 outward pass (Eq. 19) and each point's X_i^F a, X_i^F v, ω × v, R."""
    t.world_transforms(robot)
    t.velocities(robot)
    t.mv6(2 * robot.n_joints)
    t.scale6(robot.n_joints)
    t.v6(robot.n_joints)
    t.mv6(2 * n_points)
    t.mv3(3 * n_points)


def _com_ops(t, robot):
    t.world_transforms(robot)
    t.mv3(2 * robot.nb)
    t.add(3, 3, times=robot.nb)


# The runtime's calls for the whole-body functions (runtime/src/frames.cpp, centroidal.cpp,
# mass_matrix_inverse.cpp), counted with the same dense building blocks.
_WHOLE_BODY_GENERIC = {
    "frame_placements": lambda t, r, s: (t.world_transforms(r), t.mm6(len(s.frames_for(r))),
                                         t.mm3(len(s.frames_for(r)))),
    "frame_velocities": lambda t, r, s: (t.world_transforms(r), t.velocities(r), t.mv6(len(s.frames_for(r))),
                                         t.mv3(2 * len(s.frames_for(r)))),
    "frame_jacobians": lambda t, r, s: (t.world_transforms(r),
                                        _frame_jacobian_ops(t, r, [f.body for f in s.frames_for(r)])),
    "frame_bias_accelerations": lambda t, r, s: _bias_pass_ops(t, r, len(s.frames_for(r))),
    "feet_bias_accelerations": lambda t, r, s: _bias_pass_ops(t, r, len(s.feet_for(r))),
    "center_of_mass": lambda t, r, s: (_com_ops(t, r), t.velocities(r), t.mv3(2 * r.nb)),
    "center_of_mass_jacobian": lambda t, r, s: (t.world_transforms(r),
                                                _frame_jacobian_ops(t, r, range(r.nb))),
    "centroidal_momentum_matrix": lambda t, r, s: (t.crba(r), _com_ops(t, r), t.mm6(r.nb), t.mv6(r.nb)),
    "centroidal_bias": lambda t, r, s: (_com_ops(t, r), t.velocities(r), t.rnea(r, True, False), t.mm6()),
    "mass_matrix_inverse": lambda t, r, s: (t.crba(r), t.cholesky_factor(r.nv),
                                            t.add(r.nv * r.nv, r.nv * r.nv, times=r.nv)),
}


# A combined function (scene.COMBINED) against the runtime calls a user makes for its outputs (the
# angular rows and a₀ counted as the feet Jacobian and the forward dynamics).
_COMBINED_PARTS = {"step_terms": ("feet_positions", "feet_velocities", "feet_jacobian", "feet_jacobian",
                                  "mass_matrix_factor", "forward_dynamics")}


# Derivatives in the runtime (runtime/src/*derivatives*.cpp): the primal pass, then one dense
# tangent pass per direction. A tangent pass repeats the primal's products with the product rule,
# counted here as twice the primal's arithmetic without the joint transforms (computed once, then
# reused); forward dynamics adds dense
# triangular solves (n² each) of every right-hand side with the Cholesky factor.
_DERIVATIVE_DIRECTIONS = {   # name → (primal, directions as a function of (nv, n_joints, n_feet))
    "inverse_dynamics_derivatives": ("inverse_dynamics", lambda nv, nj, nf: 2 * nv),
    "bias_derivatives": ("inverse_dynamics", lambda nv, nj, nf: 2 * nv),
    "gravity_derivatives": ("gravity_terms", lambda nv, nj, nf: nv),
    "forward_dynamics_derivatives": ("forward_dynamics", lambda nv, nj, nf: 2 * nv),
    "feet_velocity_derivatives": ("feet_velocities", lambda nv, nj, nf: nv),
    "feet_force_term_derivatives": ("feet_force_terms", lambda nv, nj, nf: nv),
    "contact_dynamics_derivatives": ("contact_dynamics", lambda nv, nj, nf: 2 * nv),
}


def _generic_derivative_ops(robot, scene, name):
    primal_name, directions = _DERIVATIVE_DIRECTIONS[name]
    nv, nj, nf = robot.nv, robot.n_joints, len(scene.feet_for(robot))
    primal = generic_ops(robot, scene, primal_name)
    transforms = _Tally()
    transforms.joint_transforms(robot)
    t = _Tally()
    t.add(**{k: primal[k] for k in ("mul", "add", "div", "sqrt", "trig")})
    t.add(mul=2 * (primal["mul"] - transforms.c["mul"]), add=2 * (primal["add"] - transforms.c["add"]),
          times=directions(nv, nj, nf))
    if name == "forward_dynamics_derivatives":
        t.add(nv * nv, nv * nv, times=2 * nv + nj + 3 * nf)
    if name == "contact_dynamics_derivatives":   # per column: a Delassus solve and a solve with M
        m = 3 * len(scene.contacts_for(robot))
        t.add(nv * nv + 8 * m * m, nv * nv + 8 * m * m, times=2 * nv + nj)
    return _result(t.c)
