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
parent's own; the root keeps what reaches it (a fixed base's share is then never read: DCE). Each
piece is handed up only where that leaves fewer non-zeros to multiply by in the body and its parent
together: rotated into a tilted placement, a piece fills the parent's zeros (chain100, every piece
handed up: inverse dynamics 10 % more operations)."""

from __future__ import annotations

import collections
import itertools

from ..graph import expr as ex
from ..graph import spatial as sp
from ..graph.spatial import inertia_at_origin, snap_axis, snap_rotation


# The last few trees' parameters, by identity: a Robot's hash walks all its bodies and joints, and
# the views ask once per body (a 200-body chain: 1.3 million hashes, a second of its generation).
_KEPT = collections.OrderedDict()  # id(tree) -> (tree, parameters); holding the tree keeps its id
KEPT_TREES = 8


def body_parameters(tree):
    """((m, h, Ī), …) per body of the tree, floats: mass, first moment and rotational inertia about
    the body origin, body coordinates, after the regrouping that leaves fewer non-zeros to multiply
    by over the whole tree: every piece handed up (Khalil and Kleinfinger), or each only where that
    leaves fewer in the body and its parent. The local count misses what the tree does with the
    pieces: by it the Mini Cheetah's hips keep their masses, which the four legs' sum would have
    cancelled in the trunk (126 non-zeros every piece handed up, 138 by the local count; chain100,
    tilted, 1 582 and 699). Traced, the whole-tree count chose the fewer operations on every robot
    of the harness."""
    kept = _KEPT.get(id(tree))
    if kept is None:
        kept = _KEPT[id(tree)] = (tree, _fewest_nonzeros(tree))
        if len(_KEPT) > KEPT_TREES:
            _KEPT.popitem(last=False)
    return kept[1]


def _fewest_nonzeros(tree):
    every = _regrouped(tree, lambda options: options[0])
    fewest = _regrouped(tree, lambda options: min(options, key=lambda option: option[0]))
    read = slice(0 if tree.floating_base else 1, None)  # a fixed root's inertia is never read
    return min((every, fewest), key=lambda parameters: sum(map(_cost, parameters[read])))


def _regrouped(tree, choose):
    """The bodies' parameters with each body's pieces handed up as `choose` picks among the options
    (cost, body's, parent's), every piece handed up first, then fewer and fewer."""
    params = [(body.mass, tuple(body.mass * c for c in body.com), _rows(inertia_at_origin(body)))
              for body in tree.bodies]
    with ex.Graph():  # the pieces' images in the parents, by spatial.Inertia.congruence on constants
        for i in range(tree.nb - 1, 0, -1):
            joint, j = tree.joints[i], tree.parent[i]
            free_parent = j == 0 and not tree.floating_base  # a fixed root's inertia is never read
            placement = sp.Transform(sp.mat(snap_rotation(joint.rotation)), sp.vec(joint.translation))
            pieces = [(piece, _in_parent(placement, piece))
                      for piece in _movable_pieces(joint.type, snap_axis(joint.axis), params[i])]
            options = []
            for chosen in _subsets(pieces):  # the congruence is linear: a sum's image is the images' sum
                child = _sum([params[i]] + [_scaled(piece, -1.0) for piece, _ in chosen])
                parent = _sum([params[j]] + [image for _, image in chosen])
                left = _left_after_own(tree, j, parent)
                options.append((_cost(child) + (0 if free_parent else _cost(left)), child, parent))
            _, params[i], params[j] = choose(options)
    return tuple(params)


def _movable_pieces(joint_type, axis, parameters):
    """The pieces (m, h, Ī) that joint `joint_type` about/along `axis` never moves (module doc), each
    of which body i may hand up or keep: for a revolute joint its mass, its first moment along the
    axis and (for an axis ±e_k) α(1 − aaᵀ) with α its perpendicular entry (k + 2) mod 3 (y for z, as
    Khalil and Kleinfinger); for a prismatic one its rotational inertia."""
    m, h, ibar = parameters
    zero3, zero33 = (0.0,) * 3, _rows([[0.0] * 3] * 3)
    if joint_type != "revolute":
        return [(0.0, zero3, ibar)]
    pieces = [(m, zero3, zero33)]
    k = _coordinate_axis(axis)
    if k is not None:
        j = (k + 2) % 3
        pieces.append((0.0, tuple(h[k] if r == k else 0.0 for r in range(3)), zero33))
        pieces.append((0.0, zero3, _rows([[ibar[j][j] if r == c != k else 0.0 for c in range(3)]
                                          for r in range(3)])))
    return pieces


def _left_after_own(tree, j, parameters):
    """Body j's parameters without the entries its own pieces can clear when its turn comes (the
    greedy choice of body_parameters looks one step ahead)."""
    m, h, ibar = parameters
    if j == 0 or tree.joints[j].type != "revolute":
        return parameters
    k = _coordinate_axis(snap_axis(tree.joints[j].axis))
    if k is None:
        return 0.0, h, ibar
    cleared = (k + 2) % 3
    return (0.0, tuple(0.0 if r == k else h[r] for r in range(3)),
            _rows([[0.0 if r == c == cleared else ibar[r][c] for c in range(3)] for r in range(3)]))


def _subsets(pieces):
    """Every choice of pieces to hand up, all of them first (min keeps the first of equal costs)."""
    for n in range(len(pieces), -1, -1):
        yield from (list(chosen) for chosen in itertools.combinations(pieces, n))


def _cost(parameters):
    """The multiplications an inertia product spends on these parameters' non-zeros, roughly
    (spatial.Inertia.apply: m v three, each h entry four, each diagonal Ī entry one, each off-diagonal
    one two): exact zeros fold away, so this is what a choice of pieces changes."""
    m, h, ibar = parameters
    return (3 * (m != 0.0) + 4 * sum(x != 0.0 for x in h) + sum(ibar[k][k] != 0.0 for k in range(3))
            + 2 * sum(ibar[r][c] != 0.0 for r in range(3) for c in range(r + 1, 3)))


def _sum(terms):
    """The parameters' sum, entry by entry (spatial.snapped_sum: the pieces of a left and a right limb
    cancel in the trunk to an exact zero; as 1e-17 they cost humanoid32's bias 12 operations, Solo12's
    ID 16)."""
    entry = sp.snapped_sum
    return (entry([t[0] for t in terms]), tuple(entry([t[1][k] for t in terms]) for k in range(3)),
            _rows([[entry([t[2][r][c] for t in terms]) for c in range(3)] for r in range(3)]))


def _scaled(parameters, factor):
    m, h, ibar = parameters
    return m * factor, tuple(x * factor for x in h), _rows([[x * factor for x in row] for row in ibar])


def _rows(matrix):
    return tuple(tuple(row) for row in matrix)


def _coordinate_axis(axis):
    """k where the axis is ±e_k, else None."""
    nonzero = [k for k in range(3) if axis[k] != 0.0]
    return nonzero[0] if len(nonzero) == 1 else None


def _in_parent(placement, piece):
    """The piece in λ(i) coordinates, Xᵀ ΔI X for the joint's placement X_T: its value at every q_i,
    since X_J leaves it unchanged."""
    image = sp.Inertia.of(*piece).congruence(placement)
    return (image.m.value, tuple(x.value for x in image.h),
            _rows([[x.value for x in row] for row in image.Ibar]))
