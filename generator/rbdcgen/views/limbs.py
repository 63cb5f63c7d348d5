"""Isomorphic limbs: the trunk's subtrees that are one chain up to constants, so that their passes can
run together, one limb per SIMD lane (docs/performance.md, "One SIMD lane per leg").

Limbs are the subtrees of the trunk's children (body 0). They are isomorphic when their bodies, taken
in rbdc order (λ(i) < i, so a parent comes before its child), have the same parent positions, joint
types and joint axes; offsets, joint frames, masses and inertias may differ (they become lane
constants). Rotors and mimic couplings are not supported in lanes."""

from __future__ import annotations

from ..graph import expr as ex
from ..graph import spatial as sp
from ..errors import RbdcError


class LimbError(RbdcError):
    """The robot has no set of isomorphic limbs that fills the lanes."""


def isomorphic_limbs(robot):
    """The limbs as a tuple of ex.LANES tuples of body indices (limb k's l-th body), or LimbError."""
    roots = robot.children[0]
    if robot.couplings:
        raise LimbError("robot '%s': mimic couplings are not supported in lanes" % robot.name)
    if len(roots) != ex.LANES:
        raise LimbError("robot '%s': the trunk carries %d subtrees, lanes need %d isomorphic limbs"
                        % (robot.name, len(roots), ex.LANES))
    limbs = tuple(tuple(sorted(robot.subtree[root])) for root in roots)
    if sum(len(limb) for limb in limbs) != robot.nb - 1:
        raise LimbError("robot '%s': bodies outside the limbs" % robot.name)
    shapes = {_shape(robot, limb) for limb in limbs}
    if len(shapes) != 1:
        raise LimbError("robot '%s': the limbs differ in shape, joint types or axes" % robot.name)
    for limb in limbs:
        for body in limb:
            actuator = robot.joints[body].actuator
            if actuator is not None and actuator.rotor is not None:
                raise LimbError("robot '%s': joint '%s' has a rotor; rotors are not supported in "
                                "lanes" % (robot.name, robot.joints[body].name))
    return limbs


def _shape(robot, limb):
    """What must be equal between limbs: each body's parent (position in the limb, -1 for the
    trunk), joint type and axis."""
    position = {body: k for k, body in enumerate(limb)}
    return tuple((position.get(robot.parent[body], -1), robot.joints[body].type,
                  sp.snap_axis(robot.joints[body].axis)) for body in limb)
