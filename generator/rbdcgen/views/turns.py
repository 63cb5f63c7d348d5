"""Body frames turned about their joint axes: with views/origins.py's slides, the freedom Denavit and
Hartenberg's convention spends on making each joint placement one rotation and one offset.

A body's coordinates may turn by ψ_i about its own joint axis a_i without changing the joint's
motion, since a rotation about a_i commutes with the joint's rotation about (or translation along)
it. Everything given in body i's coordinates turns with it (its centre of mass and inertia, its
children's placements, its feet, its frames, the rotors it carries), and the joint angle takes the
rest: with R = rot(a, ψ) and E_J(q) = rot(a, q)ᵀ,

    E_T,i' = E_J(χ_i) E_T,i R_λ(i),   r_T,i' = R_λ(i)ᵀ r_T,i,   angle q_i + φ_i, φ_i = ψ_i − χ_i,

so a revolute joint's placement turns about its own axis by any χ_i, the difference going into the
sine and cosine of q_i + φ_i (one addition in joint_sincos's array, backend/emit.py), and about its
parent's axis by the parent's ψ. Those two turns are the Euler angles that leave a rotation between
two axes a single turn about a third (Denavit-Hartenberg's α): a tilted chain's placements keep 5
non-zero entries of 9. A prismatic joint has no angle to take a turn: χ_i = ψ_i. Joint
coordinates, masses and every world quantity are unchanged, so are every function's outputs.

From the root outward, each revolute joint's χ_i is the angle that leaves its placement's rotation
the fewest non-zero and non-unit entries (among the angles that zero one of them, and 0), and each
body's ψ_i the one that leaves the fewest over its children's placements (each after its own best χ),
its feet's offsets, its centre of mass and its rotational inertia, 0 on a tie. Every entry of a
turned matrix or vector is A + B cos x + C sin x in the angle x, so the angles that zero one come
in closed form."""

from __future__ import annotations

import math
from dataclasses import replace

from ..graph.spatial import snap_axis, snap_rotation, snap_vector, transpose, unit_axis_index

IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
# A sinusoid's amplitude below this has no zero worth turning for.
FLAT = 1e-15


def turned(robot):
    """The robot with each body's coordinates and each joint's placement turned by the chosen angles
    (module doc)."""
    psi, chi = _turns(robot)
    return turn(robot, psi, chi) if any(psi) or any(chi) else robot


def turn(robot, psi, chi):
    """The robot with body i's coordinates turned by psi[i] about its joint axis and its revolute
    joint's placement by chi[i] (the rest, psi[i] − chi[i], added to its angle); a prismatic joint's
    chi[i] must be its psi[i]. The same motion, the same outputs."""
    rotations = [_rotation(snap_axis(j.axis), psi[i]) if psi[i] else None for i, j in enumerate(robot.joints)]

    def into(i, point):  # Rᵀ point: body i's point in its turned coordinates
        return tuple(point) if rotations[i] is None else snap_vector(_transposed_times(rotations[i], point))

    def times(matrix, i):  # matrix R: a map from body i's coordinates, from its turned ones
        return matrix if rotations[i] is None else snap_rotation(_product(matrix, rotations[i]))

    joints = [robot.joints[0]]
    for i, joint in enumerate(robot.joints[1:], start=1):
        parent = robot.parent[i]
        if joint.type != "revolute" and chi[i] != psi[i]:
            raise ValueError("joint %s: a prismatic joint's placement turns with its body" % joint.name)
        rotation = times(snap_rotation(joint.rotation), parent)
        if chi[i]:
            rotation = snap_rotation(_product(transpose(_rotation(snap_axis(joint.axis), chi[i])), rotation))
        actuator = joint.actuator
        if actuator is not None and actuator.rotor is not None:  # carried by the parent
            rotor = actuator.rotor
            actuator = replace(actuator, rotor=replace(rotor, rotation=times(rotor.rotation, parent),
                                                       translation=into(parent, rotor.translation)))
        joints.append(replace(joint, rotation=rotation, translation=into(parent, joint.translation),
                              actuator=actuator, angle_offset=joint.angle_offset + psi[i] - chi[i]))
    bodies = tuple(body if rotations[i] is None else
                   replace(body, com=into(i, body.com),
                           inertia_com=snap_rotation(_product(transpose(rotations[i]), times(body.inertia_com, i))))
                   for i, body in enumerate(robot.bodies))
    return replace(robot, joints=tuple(joints), bodies=bodies,
                   feet=tuple(replace(f, offset=into(f.body, f.offset)) for f in robot.feet),
                   frames=tuple(replace(f, rotation=times(f.rotation, f.body), translation=into(f.body, f.translation))
                                for f in robot.frames))


def _turns(robot):
    """(ψ_i, χ_i) per body (module doc); 0 for the root and any body whose joint does not move."""
    psi, chi = [0.0] * robot.nb, [0.0] * robot.nb
    rotations = [IDENTITY] * robot.nb
    for i in range(1, robot.nb):
        joint = robot.joints[i]
        if joint.type not in ("revolute", "prismatic"):
            continue
        axis = snap_axis(joint.axis)
        own = _product(snap_rotation(joint.rotation), rotations[robot.parent[i]])  # E_T R_λ
        children = [(snap_axis(robot.joints[c].axis), robot.joints[c].type,
                     _right_turns(snap_rotation(robot.joints[c].rotation), axis)) for c in robot.children[i]]
        points = [_point_turns(point, axis) for point in
                  [robot.joints[c].translation for c in robot.children[i]]
                  + [f.offset for f in robot.feet if f.body == i] + [robot.bodies[i].com]]
        inertia = robot.bodies[i].inertia_com

        def left(x):
            """Non-zeros body i's turn by x leaves in what it carries."""
            c, s = math.cos(x), math.sin(x)
            count = sum(_own_turn(a, kind, _at(turns, c, s))[1] for a, kind, turns in children)
            count += sum(_nonzeros(_at(turns, c, s)) for turns in points)
            R = _rotation(axis, x)
            return count + _nonzeros(_product(transpose(R), _product(inertia, R)), symmetric=True)

        candidates = {0.0}
        for a, _, turns in children:  # the child's own turn leaves its axis's row: zero an entry of it
            k = unit_axis_index(a)
            candidates.update(_zeros(turns, rows=range(3) if k is None else (k,)))
        for turns in points:
            candidates.update(_zeros(turns))
        if joint.type == "revolute":
            chi[i] = _own_turn(axis, joint.type, _flat(own))[0]
            psi[i] = min(sorted(candidates), key=lambda x: (left(x), abs(x)))
        else:  # one turn for both: the placement and what the body carries
            turns = _left_turns(own, axis)
            psi[i] = chi[i] = min(sorted(candidates | set(_zeros(turns))), key=lambda x: (
                left(x) + _nonzeros(_at(turns, math.cos(x), math.sin(x))), abs(x)))
        rotations[i] = _rotation(axis, psi[i])
    return psi, chi


def _own_turn(axis, kind, matrix):
    """(χ, non-zeros) for E_J(χ) · matrix (flattened), the best turn of a revolute joint's placement
    about its own axis (0 for a prismatic one, whose placement turns with its body)."""
    if kind != "revolute":
        return 0.0, _nonzeros(matrix)
    turns = _left_turns((matrix[0:3], matrix[3:6], matrix[6:9]), axis)
    return min(((x, _nonzeros(_at(turns, math.cos(x), math.sin(x)))) for x in sorted({0.0, *_zeros(turns)})),
               key=lambda pair: (pair[1], abs(pair[0])))


# --- entries as A + B cos x + C sin x ------------------------------------------------------------
# rot(a, x) = a aᵀ + cos x (1 − a aᵀ) + sin x [a]×, so each entry of rot(a, x)ᵀ M, M rot(a, x) or
# rot(a, x)ᵀ p is a constant plus a cosine and a sine term: (A, B, C), flattened row by row.

def _parts(axis):
    outer = tuple(tuple(axis[r] * axis[c] for c in range(3)) for r in range(3))
    rest = tuple(tuple((1.0 if r == c else 0.0) - outer[r][c] for c in range(3)) for r in range(3))
    x, y, z = axis
    cross = ((0.0, -z, y), (z, 0.0, -x), (-y, x, 0.0))
    return outer, rest, cross


def _left_turns(matrix, axis):
    """rot(a, x)ᵀ matrix."""
    outer, rest, cross = _parts(axis)
    return (_flat(_product(outer, matrix)), _flat(_product(rest, matrix)),
            tuple(-v for v in _flat(_product(cross, matrix))))


def _right_turns(matrix, axis):
    """matrix rot(a, x)."""
    return tuple(_flat(_product(matrix, part)) for part in _parts(axis))


def _point_turns(point, axis):
    """rot(a, x)ᵀ point."""
    outer, rest, cross = _parts(axis)
    return (_transposed_times(outer, point), _transposed_times(rest, point), _transposed_times(cross, point))


def _at(turns, c, s):
    A, B, C = turns
    return tuple(a + b * c + k * s for a, b, k in zip(A, B, C))


def _zeros(turns, rows=None):
    """The angles in (−π, π] where an entry vanishes (of the given rows of a flattened matrix)."""
    A, B, C = turns
    entries = range(len(A)) if rows is None else [3 * r + k for r in rows for k in range(3)]
    found = []
    for e in entries:
        radius = math.hypot(B[e], C[e])
        if radius <= FLAT or abs(A[e]) > radius:
            continue
        base, spread = math.atan2(C[e], B[e]), math.acos(max(-1.0, min(1.0, -A[e] / radius)))
        found += [_wrapped(base + spread), _wrapped(base - spread)]
    return found


def _wrapped(angle):
    angle = math.remainder(angle, 2 * math.pi)
    return 0.0 if abs(angle) <= FLAT else angle


# --- small fixed-size algebra on tuples ----------------------------------------------------------

def _rotation(axis, angle):
    """rot(axis, angle), entries snapped."""
    if angle == 0.0:
        return IDENTITY
    outer, rest, cross = _parts(axis)
    c, s = math.cos(angle), math.sin(angle)
    return snap_rotation(tuple(tuple(outer[r][k] + c * rest[r][k] + s * cross[r][k] for k in range(3))
                               for r in range(3)))


def _product(a, b):
    return tuple(tuple(a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c] for c in range(3))
                 for r in range(3))



def _transposed_times(a, x):
    """aᵀ x."""
    return tuple(a[0][r] * x[0] + a[1][r] * x[1] + a[2][r] * x[2] for r in range(3))


def _flat(matrix):
    return tuple(v for row in matrix for v in row)



def _nonzeros(values, symmetric=False):
    """A turned rotation's (9 entries) multiplications: its non-zero entries and its non-unit ones; a
    vector's or a symmetric matrix's (upper triangle) non-zero entries."""
    if symmetric:
        rows = snap_rotation(values)
        return sum(rows[r][c] != 0.0 for r in range(3) for c in range(r, 3))
    snapped = snap_vector(values)
    if len(snapped) == 9:
        return sum(v != 0.0 for v in snapped) + sum(v not in (0.0, 1.0, -1.0) for v in snapped)
    return sum(v != 0.0 for v in snapped)
