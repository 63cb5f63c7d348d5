"""The coupled robot's tree (docs/model.md, "Mimic joints"): q_f = m·q_l + o.

A robot with mimic couplings is traced on its tree, every joint a coordinate of its own, with the
independent inputs expanded (q_tree = expand(q), v_tree = G v, a_tree = G a); passes/project.py
projects the outputs back onto the independent coordinates.
"""
from __future__ import annotations

from dataclasses import replace


def root_coordinates(robot):
    """(q, v) entries of the root: 7 and 6 for a floating base."""
    return (7, 6) if robot.floating_base else (0, 0)


def tree_view(robot):
    """The tree with every joint a coordinate of its own (the IR's numbering), no couplings."""
    if not robot.couplings:
        return robot
    q0, v0 = root_coordinates(robot)
    joints = [robot.joints[0]] + [replace(j, q_index=q0 + i - 1, v_index=v0 + i - 1)
                                  for i, j in enumerate(robot.joints[1:], start=1)]
    return replace(robot, nq=q0 + robot.nb - 1, nv=v0 + robot.nb - 1, joints=tuple(joints), couplings=())


def expand(robot, name, values):
    """Tree-sized q (name 'q': q_f = m·q_l + o) or v/a (G v) from the independent inputs."""
    if not robot.couplings:
        return values
    coupling = {c.follower: c for c in robot.couplings}
    q0, v0 = root_coordinates(robot)
    start = q0 if name == "q" else v0
    out = list(values[:start])
    for i in range(1, robot.nb):
        j = robot.joints[i]
        x = values[j.q_index if name == "q" else j.v_index]
        if i in coupling:
            x = coupling[i].multiplier * x + (coupling[i].offset if name == "q" else 0.0)
        out.append(x)
    return tuple(out)


def velocity_columns(robot):
    """G as, per tree velocity row, (independent column, multiplier)."""
    coupling = {c.follower: c.multiplier for c in robot.couplings}
    _, v0 = root_coordinates(robot)
    rows = [(k, 1.0) for k in range(v0)]
    rows += [(robot.joints[i].v_index, coupling.get(i, 1.0)) for i in range(1, robot.nb)]
    return rows


def dof_parents(robot, tree_parents):
    """λ over the independent dofs, from the tree's (`tree_parents`): M' = Gᵀ M G is non-zero at (k, l)
    only where a joint of k and a joint of l are one above the other in the tree, so each dof's
    ancestors are the dofs of its joints' tree ancestors. Where those sets nest as a tree's do (each
    dof's ancestors are its nearest one and that one's ancestors: a gripper's fingers coupled to one
    joint below the arm), M' factorises over that tree without fill-in; otherwise (couplings that
    join branches) every dof is the previous one's child, a dense factor."""
    column = [k for k, _ in velocity_columns(robot)]
    above = [set() for _ in range(robot.nv)]
    for i, k in enumerate(column):
        j = tree_parents[i]
        while j != -1:
            above[k].add(column[j])
            j = tree_parents[j]
    parents = []
    for k, ancestors in enumerate(above):
        ancestors.discard(k)
        parent = max(ancestors, default=-1)
        if parent >= k or ancestors != ({parent} | above[parent] if parent != -1 else set()):
            return list(range(-1, robot.nv - 1))
        parents.append(parent)
    return parents
