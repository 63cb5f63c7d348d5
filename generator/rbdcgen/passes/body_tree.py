"""What the loops over a tree's bodies share (rbdc_gen/body_tree.hpp): the tree's constants as a
BodyTree table, the bodies in depth-first order (the order of the traced transforms,
crba.body_transforms), and the operation counts of the pieces every such loop runs. Used by the
looped CRBA (looped_crba.py), the looped RNEA derivatives (looped_rnea_derivatives.py) and the looped
OSC columns (looped_osc.py)."""

from __future__ import annotations

from ..algorithms import aba
from ..algorithms.crba import depth_first_order
from ..graph.spatial import snap_axis
from ..views import regrouped

HEADER = "rbdc_gen/body_tree.hpp"
# Per call of each piece of body_tree.hpp: (multiplications, additions).
ROOT_TRANSFORM = (36, 27)   # X_0^i = X_i X_0^λ(i), below the root's children
AXIS = (9, 6)               # the joint axis in root coordinates
REVOLUTE_SUBSPACE = (6, 3)  # S = (z; p × z)
CONGRUENCE = (75, 59)       # the body's inertia in root coordinates
ACCUMULATE = (0, 10)        # into the parent's composite inertia
APPLY = (24, 18)            # F = I S
PROJECTION = (6, 5)         # Sᵀ F
CROSS = (6, 3)              # a × b
SPATIAL_CROSS = (18, 12)    # x × y, x ×* f
# Instructions the cost models count per ancestor step and per body besides the arithmetic (the
# walk, the table, the stores); the arithmetic itself as max(multiplications, additions): fused.
STEP_OVERHEAD = 4
# What one counted instruction of a tree loop costs against one of short straight-line code (the
# unit of passes/schedule.py), measured on an AMD EPYC (Zen 5), clang 14: the looped RNEA
# derivatives 0.11-0.14 ns per counted instruction on arm7, the Mini Cheetah, humanoid32 and Talos,
# short straight-line code 0.084 (arm7's ∂τ). (The looped CRBA, 0.13 on Talos, loses to the unrolled
# CRBA there by this weight too: 1.45 against 1.09 µs.)
LOOP_WEIGHT = 1.4


def ancestor_steps(robot):
    """(body, ancestor body) pairs with a joint: the force transforms of the unrolled recursions."""
    steps = 0
    for i in range(1, robot.nb):
        j = robot.parent[i]
        while j != 0:
            steps += 1
            j = robot.parent[j]
    return steps


def subtree_ends(parents):
    """end[i]: one past body i's last descendant when `parents` is depth-first numbered (the subtree
    of i is then i … end − 1)."""
    end = list(range(1, len(parents) + 1))
    for i in range(len(parents) - 1, 0, -1):
        end[parents[i]] = max(end[parents[i]], end[i])
    return end


def table_parents(robot):
    """The parents in depth-first order (crba.depth_first_order), as the table holds them."""
    order = depth_first_order(robot)
    position = {body: k for k, body in enumerate(order)}
    return [position[robot.parent[i]] if i else -1 for i in order]


def applies(robot):
    """A tree whose dynamics are its bodies' alone (aba.applies: no rotors, no couplings, both of which
    add terms the loops do not model), with at least one joint."""
    return robot.nb > 1 and aba.applies(robot)


def _upper(matrix):
    return [matrix[0][0], matrix[0][1], matrix[0][2], matrix[1][1], matrix[1][2], matrix[2][2]]


def table(robot):
    """The tree's constants as the BodyTree initialiser `tree`, the bodies in depth-first order."""
    order = depth_first_order(robot)
    parents = table_parents(robot)

    def row(values):
        return "{" + ", ".join(values) + "}"

    def number(x):
        return repr(float(x))

    joints = [robot.joints[i] for i in order]
    no_axis = [0.0, 0.0, 0.0]  # the root's
    axes = [snap_axis(joint.axis) if k else no_axis for k, joint in enumerate(joints)]
    parameters = [regrouped.body_parameters(robot)[i] for i in order]
    moments = [h for _, h, _ in parameters]
    rotational = [_upper(ibar) for _, _, ibar in parameters]

    def components(vectors, n):  # component by component, as BodyTree holds them
        return row(row(number(vector[k]) for vector in vectors) for k in range(n))

    fields = [
        row(map(str, parents)),
        row(map(str, subtree_ends(parents))),
        row(str(joint.v_index if k else -1) for k, joint in enumerate(joints)),
        row(cpp_bool(k and joint.type == "revolute") for k, joint in enumerate(joints)),
        components(axes, 3),
        row(number(mass) for mass, _, _ in parameters),
        components(moments, 3),
        components(rotational, 6),
        row(number(joint.actuator.armature if k and joint.actuator else 0.0) for k, joint in enumerate(joints)),
        cpp_bool(depth_first_dofs(joints)), cpp_bool(depth_first_dofs(joints) and is_chain(parents))]
    return f"RBDC_TABLE BodyTree<{robot.nb}> tree{{{', '.join(fields)}}};"


def cpp_bool(flag):
    return "true" if flag else "false"


def depth_first_dofs(joints):
    """Whether the table's bodies 1, 2, … have consecutive dofs (a robot loaded from a URDF): then a
    body's subtree is one run of dofs."""
    return all(joints[k].v_index == joints[1].v_index + k - 1 for k in range(1, len(joints)))


def is_chain(parents):
    """Whether every body but the last has one child, numbered next."""
    return all(parents[k] == k - 1 for k in range(2, len(parents)))


def fixed_base_chain(robot):
    """A fixed-base chain of bodies alone (applies), dofs numbered along it: the articulated-body
    recursion's loops (articulated_inverse.py) and ∂q̈'s low-rank form."""
    if robot.floating_base or not applies(robot):
        return False
    return is_chain(table_parents(robot)) and depth_first_dofs([robot.joints[i] for i in depth_first_order(robot)])


def root_frame_pieces(robot):
    """The pieces root_frames and root_inertias run: per body its frame, axis, subspace (p0 × z for
    every joint, the prismatic ones selecting z instead), inertia."""
    pieces = []
    for i in range(1, robot.nb):
        pieces += [AXIS, REVOLUTE_SUBSPACE, CONGRUENCE]
        pieces += [ROOT_TRANSFORM] if robot.parent[i] != 0 else []
    return pieces

