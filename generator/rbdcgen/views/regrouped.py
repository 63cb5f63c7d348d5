"""Each body's inertia with the part its joint cannot move handed to its parent: the regrouping of
Khalil and Kleinfinger ("Minimum operations and minimum parameters of the dynamic models of tree
structure robots", 1987), written for any joint frame instead of modified Denavit-Hartenberg ones.

A piece ΔI of body i's spatial inertia may ride on λ(i) instead of on i when the joint's motion never
changes it: ΔI is the same in λ(i)'s coordinates at every q_i, and ΔI S_i = 0 (the joint's own motion
gives it no momentum). Then the kinetic and potential energy, every body's momentum summed (hence M,
c, g, τ, their derivatives, the centre of mass and the centroidal quantities) are unchanged, while
body i's inertia becomes sparser, and a sparser inertia folds away operations in every pass that
multiplies by it. The pieces (S_i = (a; 0) revolute about a through the origin, (0; a) prismatic):

- revolute: mass m, first moment s·a along the axis, rotational α (1 − a aᵀ): body i keeps no mass,
  no first moment along its axis and, for an axis along a coordinate axis, a zero where α is taken;
- prismatic: the whole rotational inertia about the origin (m = 0, h = 0): body i keeps m and h.

Bodies are visited from the leaves to the root, so a piece handed to a parent moves on with the
parent's own; the root keeps what reaches it (a fixed base's share is then never read: DCE)."""

from __future__ import annotations

from ..graph.spatial import inertia_at_origin, snap_axis, snap_rotation


def body_parameters(tree):
    """((m, h, Ī), …) per body of the tree, floats: mass, first moment and rotational inertia about
    the body origin, body coordinates, after the regrouping."""
    params = [[body.mass, [body.mass * c for c in body.com], [list(r) for r in inertia_at_origin(body)]]
              for body in tree.bodies]
    for i in range(tree.nb - 1, 0, -1):
        joint = tree.joints[i]
        piece = _movable_piece(joint.type, snap_axis(joint.axis), *params[i])
        for k in range(3):
            params[i][1][k] -= piece[1][k]
            for c in range(3):
                params[i][2][k][c] -= piece[2][k][c]
        params[i][0] -= piece[0]
        moved = _in_parent(joint, piece)
        parent = params[tree.parent[i]]
        parent[0] += moved[0]
        for k in range(3):
            parent[1][k] += moved[1][k]
            for c in range(3):
                parent[2][k][c] += moved[2][k][c]
    return tuple((m, tuple(h), tuple(tuple(r) for r in ibar)) for m, h, ibar in params)


def _coordinate_axis(axis):
    """k where the axis is ±e_k, else None."""
    nonzero = [k for k in range(3) if axis[k] != 0.0]
    return nonzero[0] if len(nonzero) == 1 else None


def _movable_piece(joint_type, axis, m, h, ibar):
    """(m, h, Ī) of the largest piece joint `joint_type` about/along `axis` never moves (module doc)."""
    zero = [[0.0] * 3 for _ in range(3)]
    if joint_type != "revolute":
        return 0.0, [0.0] * 3, [list(r) for r in ibar]
    k = _coordinate_axis(axis)
    if k is None:  # a tilted axis: the mass alone, so that h and Ī keep their zeros
        return m, [0.0] * 3, zero
    s = h[k]
    j = (k + 2) % 3  # the perpendicular entry zeroed: y for a z axis, as Khalil and Kleinfinger
    alpha = ibar[j][j]
    piece = [[alpha if r == c and r != k else 0.0 for c in range(3)] for r in range(3)]
    return m, [s if r == k else 0.0 for r in range(3)], piece


def _in_parent(joint, piece):
    """The piece in λ(i) coordinates: Xᵀ ΔI X for X_T = (E, r) (spatial.Inertia.congruence), which is
    its value at every q_i since X_J leaves it unchanged."""
    m, h, ibar = piece
    E, r = snap_rotation(joint.rotation), joint.translation
    y = [sum(E[a][k] * h[a] for a in range(3)) for k in range(3)]                    # Eᵀ h
    rotated = [[sum(E[a][k] * ibar[a][b] * E[b][c] for a in range(3) for b in range(3))
                for c in range(3)] for k in range(3)]                               # Eᵀ Ī E
    h_new = [y[k] + m * r[k] for k in range(3)]
    rs, ys, hs = _skew(r), _skew(y), _skew(h_new)
    shift = [[sum(rs[a][k] * ys[k][b] + hs[a][k] * rs[k][b] for k in range(3)) for b in range(3)]
             for a in range(3)]
    return m, h_new, [[rotated[a][b] - shift[a][b] for b in range(3)] for a in range(3)]


def _skew(v):
    return [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]
