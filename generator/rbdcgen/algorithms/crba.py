"""Composite-rigid-body algorithm (paper 000 Alg. 5, Eqs. 26-29).

Composite inertias stay in (m, h, Ī) form and are moved to the parent with the structured
congruence of spatial.Inertia; F_i = I_ci S_i is carried towards the root through (X_λ(j)^j)ᵀ.
Only the entries H_ij with i ∈ ν(j) or j ∈ ν(i) are computed; the rest are structural zeros and the
upper triangle is mirrored."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp


def mass_matrix(m):
    robot = m.robot
    nv = robot.nv
    zero = ex.const(0.0)
    H = [[zero] * nv for _ in range(nv)]
    composite = [m.inertia(i) for i in range(robot.nb)]        # I_ci ← I_i
    waiting = {}  # pair body → (a child's F in its coordinates, the child's column)
    for i in range(1, robot.nb):                               # rotor i rides on λ(i)
        if m.rotor(i) is not None:
            X_rot, _, rotor_inertia = m.rotor(i)
            j = robot.parent[i]
            composite[j] = composite[j] + rotor_inertia.congruence(X_rot)
    for i in range(robot.nb - 1, 0, -1):
        m.mark("inward pass, composite inertias (CRBA)", i)
        j = robot.parent[i]
        X = m.X_up(i)
        composite[j] = composite[j] + m.into_parent(i, X.congruence(composite[i]))  # Eq. 26
        F = composite[i].apply(m.motion_subspace(i))             # Eq. 28: F_i = I_ci S_i
        col = m.joint(i).v_index
        H[col][col] = sp.dot(m.motion_subspace(i), F)             # H_ii = S_iᵀ F_i
        rotor_force = None
        if m.rotor(i) is not None:
            # The rotor's spin needs F_r = I_rot S_rot (constant): H_ii += S_rotᵀ F_r, and X_rotᵀ F_r
            # joins F_i on the carrier λ(i), so the rows of κ(λ(i)) and the trunk block take it.
            X_rot, S_rot, rotor_inertia = m.rotor(i)
            F_r = rotor_inertia.apply(S_rot)
            H[col][col] = H[col][col] + sp.dot(S_rot, F_r)
            rotor_force = X_rot.force_T(F_r)
        if m.armature(i):
            H[col][col] = H[col][col] + m.armature(i)             # reflected inertia, diagonal only

        def to_parent(body, F):
            F = m.X_up(body).force_T(F)
            return sp.vadd(F, rotor_force) if body == i and rotor_force is not None else F

        # A limb pair fills lanes 2 and 3 with lanes 0 and 1 again (views/limbs.py): there a pair
        # body's walk to the root carries a child's F, which joins it one step up; the child's
        # entries are read from lanes 2-3 where they are stored (lane_get of a rotation: no shuffle).
        columns = [(col, lambda x: x)] + ([(waiting[i][1], ex.swap_lane_halves)] if i in waiting else [])
        if i in waiting:
            F = sp.pack_halves(F, waiting.pop(i)[0])
        j = robot.parent[i]
        if m.spare_lanes(i) and m.spare_lanes(j) and j not in waiting and len(columns) == 1:
            F = to_parent(i, F)                                   # one step alone, then the parent's walk
            waiting[j] = (F, col)
            row = m.joint(j).v_index
            H[row][col] = H[col][row] = sp.dot(m.motion_subspace(j), F)
            continue
        body = i
        while robot.parent[body] != 0:                            # Eq. 27, j ∈ κ(i)
            F = to_parent(body, F)
            body = robot.parent[body]
            row = m.joint(body).v_index
            entry = sp.dot(m.motion_subspace(body), F)
            for c, lanes in columns:
                H[row][c] = H[c][row] = lanes(entry)
        if robot.floating_base:
            F = to_parent(body, F)                                # F_i in trunk coordinates
            for r in range(6):
                for c, lanes in columns:
                    H[r][c] = H[c][r] = lanes(F[r])
    if robot.floating_base:
        I0 = composite[0].dense()                                 # H_00 = I_c0 (Eq. 29)
        for r in range(6):
            for c in range(6):
                H[r][c] = I0[min(r, c)][max(r, c)]
    return H


def depth_first_order(robot):
    """The bodies in depth-first order, the root first and children in index order: the numbering
    itself for a robot loaded from a URDF; a regular topology file may number otherwise."""
    children = [[] for _ in range(robot.nb)]
    for i in range(1, robot.nb):
        children[robot.parent[i]].append(i)
    order, stack = [], [0]
    while stack:
        i = stack.pop()
        order.append(i)
        stack.extend(reversed(children[i]))
    return order


def body_transforms(m):
    """X_λ(i)^i = X_J(q_i) X_T(i) of every body i ≥ 1 as one transform, E row-major then r, the
    bodies in depth_first_order: what the looped CRBA (rbdc_gen/crba.hpp, passes/looped_crba.py)
    reads."""
    return tuple(x for i in depth_first_order(m.robot)[1:] for x in body_transform(m, i))


def body_transform(m, i):
    """Body i's X_λ(i)^i as body_transforms stores it: 12 values, E row-major then r."""
    m.mark("body transforms", i)
    X = m.X_tree(i).then(m.X_joint(i))
    E = sp.identity3() if X.E is None else X.E
    r = sp.zeros(3) if X.r is None else X.r
    return tuple(e for row in E for e in row) + tuple(r)


# The doc of the output M of mass_matrix_lower and its lane version.
LOWER_TRIANGLE_DOC = ("mass matrix, lower triangle (row ≥ column); the entries above the diagonal "
                      "are not written")


def lower_triangle(entries, n):
    """The column-major n × n `entries` with those above the diagonal (row < column) marked None:
    not written (mass_matrix_lower, whose callers read M through its lower triangle)."""
    return tuple(None if k % n < k // n else e for k, e in enumerate(entries))
