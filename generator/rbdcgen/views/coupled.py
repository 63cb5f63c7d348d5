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
