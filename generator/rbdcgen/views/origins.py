"""Body origins slid along their joint axes: the tree the functions are traced on (passes/schedule.py,
trace_scene), with the same motion and fewer non-zero placement entries to multiply by.

A body's coordinates may move by d along its own joint axis a without changing the joint's motion: a
rotation about a (or a translation along it) commutes with the slide, so the joint's placement takes
it, r_i' = r_i − d_λ a_λ + d_i E_Tᵀ a_i, and everything given in body i's coordinates moves by −d_i a_i
(its centre of mass, its children's placements, its feet, its frames, the rotors it carries). Joint
coordinates, masses and every world quantity are unchanged, so are M, c, g, τ, q̈, their derivatives,
the feet's and frames' poses, velocities and Jacobians. This is the freedom Denavit and Hartenberg's
convention spends on placing each origin on the common normal: where an axis points along a
placement, one entry of it (or of a child's) can be made zero. iiwa14's placements (0, 0, 0.1575),
(0, 0, 0.2025), (0, 0.2045, 0), (0, 0, 0.2155), … along axes that alternate between its links' z and
y become 0, (0, 0, 0.36), 0, (0, 0, 0.42), 0, (0, 0, 0.4), 0: 7 non-zero translation entries become 3,
its inverse dynamics 11 % fewer operations.

Each d_i is chosen from the root outward among the values that zero an entry of the joint's own
placement, of a child's or of a foot's on the body (or 0), by the fewest non-zero entries they leave
in all of them, the smallest slide on a tie; a slide never adds a non-zero entry to them over the
tree. (A foot on the joint axis counts: slid off the origin it would cost the feet's functions a
lever arm whose torque about the axis is a round-off residue, not an exact zero.) The body's inertia
about its new origin changes too (its first moment along a, which views/regrouped.py hands to the
parent anyway, and two products of inertia), and so do the frames at its origin, which only the
frame functions read; the count leaves both out."""

from __future__ import annotations

from dataclasses import replace

from ..graph.spatial import snap_axis, snap_rotation, snapped_sum


def slid(robot):
    """The robot with each revolute or prismatic body's origin slid along its joint axis (module doc)."""
    slides = _slides(robot)
    if not any(slides):
        return robot

    def moved(i, point):
        return _moved(robot, slides, i, point)

    joints = [robot.joints[0]]
    for i, joint in enumerate(robot.joints[1:], start=1):
        parent = robot.parent[i]
        own = _axis_in_parent(joint)
        translation = _shifted(moved(parent, joint.translation), own, slides[i])
        actuator = joint.actuator
        if actuator is not None and actuator.rotor is not None:  # carried by the parent
            actuator = replace(actuator, rotor=replace(actuator.rotor,
                                                       translation=moved(parent, actuator.rotor.translation)))
        joints.append(replace(joint, translation=translation, actuator=actuator))
    return replace(robot, joints=tuple(joints),
                   bodies=tuple(replace(b, com=moved(i, b.com)) for i, b in enumerate(robot.bodies)),
                   feet=tuple(replace(f, offset=moved(f.body, f.offset)) for f in robot.feet),
                   frames=tuple(replace(f, translation=moved(f.body, f.translation)) for f in robot.frames))


def _slides(robot):
    """d_i per body (0 for the root and any body whose joint is neither revolute nor prismatic)."""
    slides = [0.0] * robot.nb
    for i in range(1, robot.nb):
        joint = robot.joints[i]
        if joint.type not in ("revolute", "prismatic"):
            continue
        own = _moved(robot, slides, robot.parent[i], joint.translation)
        along, axis = _axis_in_parent(joint), snap_axis(joint.axis)
        carried = [robot.joints[c].translation for c in robot.children[i]]  # in body i's coordinates
        carried += [foot.offset for foot in robot.feet if foot.body == i]
        candidates = {0.0}
        candidates.update(-x / u for x, u in zip(own, along) if u != 0.0)
        candidates.update(x / a for point in carried for x, a in zip(point, axis) if a != 0.0)

        def left(d):
            entries = _shifted(own, along, d) + tuple(x for point in carried for x in _shifted(point, axis, -d))
            return sum(x != 0.0 for x in entries), abs(d)

        slides[i] = min(sorted(candidates), key=left)
    return slides


def _moved(robot, slides, i, point):
    """A point given in body i's coordinates, in its slid ones."""
    return _shifted(point, snap_axis(robot.joints[i].axis), -slides[i]) if slides[i] else tuple(point)


def _axis_in_parent(joint):
    """The joint axis in the parent's coordinates, E_Tᵀ a."""
    rotation, axis = snap_rotation(joint.rotation), snap_axis(joint.axis)
    return tuple(sum(rotation[r][k] * axis[r] for r in range(3)) for k in range(3))


def _shifted(point, direction, d):
    """point + d · direction, entry by entry (spatial.snapped_sum: 0.2025 − 0.2025 through a rotation's
    snapped entries, or a tilted axis's quotient, is the zero a slide meant)."""
    return tuple(snapped_sum([x, d * u]) for x, u in zip(point, direction))
