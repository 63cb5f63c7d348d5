"""Isomorphic limbs: subtrees hanging from one body that are one chain up to constants, so that
their passes can run together, one limb per SIMD lane (docs/performance.md, "One SIMD lane per
leg", "Limbs in pairs").

Limbs are isomorphic when their bodies, taken in rbdc order (λ(i) < i, so a parent comes before its
child), have the same parent positions, joint types and joint axes; offsets, joint frames, masses and
inertias may differ (they become lane constants). A group is 4 such limbs of one body (a quadruped's
legs: one limb per lane), or 2 or 3 (a humanoid's legs, its arms: the lanes past the limbs repeat
them, so a pair costs what one limb does on a 2-wide vector); more limbs of one shape are split into
groups of 4 and a last group of 2 or 3 (a hexapod's six legs: 4 + 2). The bodies in no group, the
spine, stay scalar. Rotors and mimic couplings are not supported in lanes."""

from __future__ import annotations

from dataclasses import dataclass

from ..graph import expr as ex
from ..graph import spatial as sp
from ..errors import RbdcError


class LimbError(RbdcError):
    """The robot has no set of isomorphic limbs that fills the lanes."""


@dataclass(frozen=True)
class LimbGroup:
    """Isomorphic limbs of the spine body `parent`: per limb its bodies in rbdc order."""
    parent: int
    limbs: tuple

    @property
    def lanes(self):
        """The limb in each of the ex.LANES lanes: limb k % n in lane k (a pair fills lanes 2 and 3 with
        limbs 0 and 1 again)."""
        return tuple(self.limbs[k % len(self.limbs)] for k in range(ex.LANES))

    @property
    def spare_lanes(self):
        """Whether lanes 2-3 only repeat lanes 0-1 (a pair), free to carry a second quantity."""
        return 2 * len(self.limbs) == ex.LANES

    @property
    def live(self):
        """The lanes whose values are the limbs' own (the others repeat them)."""
        return range(len(self.limbs))


def limb_groups(robot):
    """The robot's groups of isomorphic limbs (LimbGroup, by their bodies' order), or LimbError: from
    the trunk outward, a body's children whose subtrees share one shape and carry no rotor form
    groups of up to ex.LANES limbs, none of one (4 + 2 for six, 3 + 2 for five); every other child is
    a spine body, searched in turn."""
    if robot.couplings:
        raise LimbError("robot '%s': mimic couplings are not supported in lanes" % robot.name)
    groups = []

    def search(body):
        if len(robot.children[body]) == 1:  # a chain's link: no group here (and no O(depth) shape per link)
            return search(robot.children[body][0])
        by_shape = {}
        for child in robot.children[body]:
            limb = tuple(sorted(robot.subtree[child]))
            by_shape.setdefault(_shape(robot, limb), []).append(limb)
        for limbs in by_shape.values():
            if len(limbs) > 1 and not any(_has_rotor(robot, limb) for limb in limbs):
                groups.extend(LimbGroup(body, chunk) for chunk in _chunks(tuple(limbs)))
            else:
                for limb in limbs:
                    search(limb[0])

    search(0)
    if not groups:
        raise LimbError("robot '%s': no body carries two or more isomorphic limbs without rotors" % robot.name)
    return tuple(sorted(groups, key=lambda group: group.limbs[0][0]))


def _chunks(limbs):
    """Limbs in groups of ex.LANES, the last of at least 2 (five: 3 + 2)."""
    if len(limbs) <= ex.LANES:
        return [limbs]
    first = ex.LANES if len(limbs) - ex.LANES >= 2 else ex.LANES - 1
    return [limbs[:first]] + _chunks(limbs[first:])


def isomorphic_limbs(robot):
    """The limbs as a tuple of ex.LANES tuples of body indices (limb k's l-th body), when the trunk
    carries exactly ex.LANES isomorphic limbs and nothing else (a quadruped: what the lane
    derivatives, contacts, feet and frames need), or LimbError."""
    groups = limb_groups(robot)
    limbs = groups[0].limbs
    if len(groups) > 1 or groups[0].parent != 0 or len(limbs) != ex.LANES or sum(map(len, limbs)) != robot.nb - 1:
        raise LimbError("robot '%s': lanes for these functions need the trunk to carry %d isomorphic limbs "
                        "and nothing else; it has %s" % (robot.name, ex.LANES, _in_words(robot, groups)))
    return limbs


def quadruped_groups(robot):
    """isomorphic_limbs as the one group of the trunk."""
    return (LimbGroup(0, isomorphic_limbs(robot)),)


def groups_in_words(robot):
    """What limb_groups puts in lanes, for the header's schedule line; None for the quadruped's four
    limbs of the trunk (isomorphic_limbs)."""
    try:
        isomorphic_limbs(robot)
        return None
    except LimbError:
        pass
    return "the isomorphic limbs in SIMD lanes: %s (a group of fewer than %d repeated to fill the lanes)" % (
        _in_words(robot, limb_groups(robot)), ex.LANES)


def _in_words(robot, groups):
    return ", ".join("%d of %s" % (len(g.limbs), robot.bodies[g.parent].name) for g in groups)


def _has_rotor(robot, limb):
    return any(robot.joints[body].actuator is not None and robot.joints[body].actuator.rotor is not None
               for body in limb)


def _shape(robot, limb):
    """What must be equal between limbs: each body's parent (position in the limb, -1 for the
    spine body it hangs from), joint type and axis."""
    position = {body: k for k, body in enumerate(limb)}
    return tuple((position.get(robot.parent[body], -1), robot.joints[body].type,
                  sp.snap_axis(robot.joints[body].axis)) for body in limb)
