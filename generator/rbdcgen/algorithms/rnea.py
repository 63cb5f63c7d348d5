"""The recursive Newton-Euler passes of paper 000 Section 4: quadratic velocity terms (Alg. 2),
gravity terms (Alg. 3), external wrench terms from foot forces (Alg. 4) and the full inverse
dynamics M a + c + g, all one outward and one inward pass with different inputs."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from .kinematics import body_velocity


def foot_wrenches(m, frames=None):
    """Alg. 4 outward loop: the world foot forces as wrenches on their bodies at the body origin,
    body coordinates: F_i = R_iᵀ f_k, f_i += (r_fk × F_i, F_i) (force transform of Eq. 7). R_iᵀ f_k
    from `frames` (world_frames) where the caller has them anyway, else f_k rotated down the foot's
    path (in_body)."""
    wrenches = [None] * m.robot.nb
    for k, foot in enumerate(m.feet):
        m.mark("force of foot " + foot.name)
        force = (sp.mat_tmatvec(frames[foot.body][0], m.foot_force(k)) if frames is not None
                 else in_body(m, foot.body, m.foot_force(k)))
        wrench = sp.cross(sp.vec(foot.offset), force) + force
        i = foot.body
        wrenches[i] = wrench if wrenches[i] is None else sp.vadd(wrenches[i], wrench)
    return wrenches


def in_body(m, body, vector):
    """A world vector in body coordinates, R_bodyᵀ x: R_0ᵀ x, then each joint's rotations E down the
    path (R_i = R_λ(i) E_1ᵀ E_2ᵀ for X_up(i)'s factors 1, 2): a matrix-vector product a rotation,
    where world_frames composes matrices (forward dynamics: humanoid32 5 877 → 5 655 instructions,
    arm7 1 536 → 1 461)."""
    path = []
    while body > 0:
        path.append(body)
        body = m.robot.parent[body]
    x = sp.mat_tmatvec(m.base_rotation(), vector)
    for i in reversed(path):
        for factor in m.X_up(i).factors:
            if factor.E is not None:
                x = sp.matvec(factor.E, x)
    return x


def inward_pass(m, forces, rotor_forces=None, root_wrench=False):
    """Alg. 2-4 inward loop: c_i = S_iᵀ f_i, f_λ(i) += (X_λ(i)^i)ᵀ f_i (Eqs. 22-23); the root
    block c₀ = S₀ᵀ f₀ = f₀ for a floating base. Returns the joint-space vector (length nv).
    Rotor i's wrench (rotor_wrenches) also drives joint i and loads its carrier:
    c_i += S_rotᵀ f_rot, f_λ(i) += X_rotᵀ f_rot. With root_wrench, f₀ leads the result also for a
    fixed base (the whole tree's wrench at the root, the centroidal bias)."""
    forces = list(forces)
    tau = [None] * m.robot.nb
    for i in range(m.robot.nb - 1, 0, -1):
        m.mark("inward pass", i)
        j = m.robot.parent[i]
        tau[i] = sp.dot(m.motion_subspace(i), forces[i])
        forces[j] = sp.vadd(forces[j], m.into_parent(i, m.X_up(i).force_T(forces[i])))
        if rotor_forces is not None and rotor_forces[i] is not None:
            X_rot, S_rot, _ = m.rotor(i)
            tau[i] = tau[i] + sp.dot(S_rot, rotor_forces[i])
            forces[j] = sp.vadd(forces[j], m.into_parent(i, X_rot.force_T(rotor_forces[i])))
    root = list(forces[0]) if m.robot.floating_base or root_wrench else []
    return tuple(root + tau[1:])


def rotor_wrenches(m, velocities, accelerations, joint_accelerations):
    """Each rotor's wrench at its origin, rotor coordinates (runtime/src/rotors.hpp), or None for a
    robot without rotors: Eqs. 19-20 with X_rot, S_rot on the carrier j = λ(i),
        v_r = X_rot v_j + S_rot q̇_i,  a_r = X_rot a_j + S_rot q̈_i + v_r × S_rot q̇_i,
        f_r = I_rot a_r + v_r ×* I_rot v_r,
    the velocity terms only with `velocities`, the q̈ term only with `joint_accelerations`."""
    rotors = [None] + [m.rotor(i) for i in range(1, m.robot.nb)]
    if not any(rotors):
        return None
    wrenches = [None] * m.robot.nb
    for i in range(1, m.robot.nb):
        if rotors[i] is None:
            continue
        m.mark("rotor of joint " + m.joint(i).name)
        X_rot, S_rot, inertia = rotors[i]
        j = m.robot.parent[i]
        a_r = X_rot.motion(accelerations[j])
        if joint_accelerations is not None:
            a_r = sp.vadd(a_r, sp.vscale(joint_accelerations[i], S_rot))
        if velocities is None:
            wrenches[i] = inertia.apply(a_r)
            continue
        spin = sp.vscale(m.vi(i), S_rot)
        v_r = sp.vadd(X_rot.motion(velocities[j]), spin)
        a_r = sp.vadd(a_r, sp.crm(v_r, spin))
        wrenches[i] = sp.vadd(inertia.apply(a_r), sp.crf(v_r, inertia.apply(v_r)))
    return wrenches


def rnea(m, base_acceleration, joint_accelerations, with_velocity, external=None, root_wrench=False):
    """One outward pass (Eqs. 19-20, 24) and the inward pass:
        a_i = X_λ(i)^i a_λ(i) + v_i × S_i q̇_i + S_i q̈_i,   f_i = I_i a_i + v_i ×* I_i v_i − f_i^ext.
    `base_acceleration` is a₀ (bias and gravity included), `joint_accelerations[i]` q̈_i or None,
    `with_velocity` enables the velocity product terms, `external` the body wrenches. Rotors take
    part as bodies of their own (rotor_wrenches). A limb pair's bodies carry a and v in one lane
    value (pair_step, sp.pack_halves)."""
    nb = m.robot.nb
    velocities = [m.base_velocity()] if with_velocity else None
    accelerations = [base_acceleration]
    packed = {}  # pair body → its motion (a_i | v_i), pair_step
    forces = []
    for i in range(nb):  # body by body, so that a body's velocity and acceleration die with its children's
        m.mark("outward pass", i)
        if i > 0 and with_velocity and m.spare_lanes(i):
            j = m.robot.parent[i]
            parent = packed[j] if j in packed else sp.pack_halves(accelerations[j], velocities[j])
            q_dd = None if joint_accelerations is None else joint_accelerations[i]
            packed[i], f_i = pair_step(m, i, parent, q_dd)
            velocities.append(None)  # read by no rotor: limbs in lanes have none
            accelerations.append(None)
        else:
            if i > 0:
                j = m.robot.parent[i]
                S = m.motion_subspace(i)
                a_i = m.X_up(i).motion(accelerations[j])
                if with_velocity:
                    velocities.append(body_velocity(m, i, velocities[j]))
                    a_i = sp.vadd(a_i, sp.crm(velocities[i], sp.vscale(m.vi(i), S)))
                if joint_accelerations is not None:
                    a_i = sp.vadd(a_i, sp.vscale(joint_accelerations[i], S))
                accelerations.append(a_i)
            inertia = m.inertia(i)
            f_i = inertia.apply(accelerations[i])
            if with_velocity:
                f_i = sp.vadd(f_i, sp.crf(velocities[i], inertia.apply(velocities[i])))
        if external is not None and external[i] is not None:
            f_i = sp.vsub(f_i, external[i])
        forces.append(f_i)
    return inward_pass(m, forces, rotor_wrenches(m, velocities, accelerations, joint_accelerations),
                       root_wrench)


# A limb pair fills lanes 2 and 3 with lanes 0 and 1 again (views/limbs.py); its outward pass puts
# v_i there instead, so that one transform and one inertia product serve a_i and v_i.
def pair_step(m, i, parent, q_dd):
    """Pair body i's outward step and wrench on (a | v) values (lanes 0-1 the pair's a, 2-3 its v):
        (a_i | v_i) = X (a_λ(i) | v_λ(i)) + S (q̈_i | q̇_i) + swap(0 | v_i × S q̇_i),
        f_i = I (a_i | v_i) + swap(· | v_i ×* I v_i),
    swap exchanging the halves (sp.swap_halves), the cross products taken of the whole value and
    kept in the half where they are right. Returns (a_i | v_i) and f_i, good in lanes 0 and 1."""
    S = m.motion_subspace(i)
    rates = ex.pack_lane_halves(ex.const(0.0), m.vi(i))  # (0 | q̇_i)
    steps = rates if q_dd is None else ex.pack_lane_halves(q_dd, m.vi(i))
    carried = m.X_up(i).motion(parent)  # v_i × S q̇_i = (X v_λ(i)) × S q̇_i: S × S = 0
    motion = sp.vadd(sp.vadd(carried, sp.vscale(steps, S)), sp.swap_halves(sp.crm(carried, sp.vscale(rates, S))))
    momentum = m.inertia(i).apply(motion)
    return motion, sp.vadd(momentum, sp.swap_halves(sp.crf(motion, momentum)))


def velocity_bias(m):
    """a₀ = (0, −ω̃₀ v₀) of Alg. 2: the trunk's classical-to-spatial acceleration correction."""
    v0 = m.base_velocity()
    return sp.zeros(3) + sp.vneg(sp.cross(sp.ang(v0), sp.lin(v0)))


def gravity_acceleration(m):
    """a₀ = −(0, R_W^0 g) of Alg. 3: gravity as a fictitious upward trunk acceleration."""
    return sp.zeros(3) + sp.vneg(m.gravity_in_base())


def quadratic_velocity_terms(m):
    """c of Alg. 2."""
    return rnea(m, velocity_bias(m), None, True)


def gravity_terms(m):
    """g of Alg. 3."""
    return rnea(m, gravity_acceleration(m), None, False)


def feet_force_terms(m):
    """τ_e of Alg. 4 from the world foot forces (τ_e = Jᵀ f)."""
    return inward_pass(m, [w if w is not None else sp.zeros(6) for w in foot_wrenches(m)])


def joint_accelerations(m):
    return [None] + [m.ai(i) for i in range(1, m.robot.nb)]


def base_acceleration(m, trunk_acceleration):
    """The trunk's spatial acceleration in the fictitious-gravity frame: the classical trunk
    acceleration (ω̇, R_W^0 p̈) of conventions.md plus the Alg. 2 and Alg. 3 terms."""
    return sp.vadd(sp.vadd(trunk_acceleration, velocity_bias(m)), gravity_acceleration(m))


def bias(m):
    """c + g in one pass: inverse dynamics at a = 0, the accelerations' terms never traced."""
    return rnea(m, base_acceleration(m, sp.zeros(6)), None, True)


def inverse_dynamics(m):
    """M a + c + g: Alg. 2 and 3 with the accelerations added (paper 000 Eq. 29), plus each joint's
    armature: τ_i += armature_i q̈_i (reflected inertia on M's diagonal only)."""
    trunk = m.a[0:6] if m.robot.floating_base else sp.zeros(6)
    tau = list(rnea(m, base_acceleration(m, trunk), joint_accelerations(m), True))
    for i in range(1, m.robot.nb):
        if m.armature(i):
            k = m.joint(i).v_index
            tau[k] = tau[k] + m.armature(i) * m.ai(i)
    return tuple(tau)


def bias_minus_external(m):
    """c + g − τ_e in one pass (forward dynamics right-hand side)."""
    external = foot_wrenches(m) if m.feet else None
    return rnea(m, base_acceleration(m, sp.zeros(6)), None, True, external)
