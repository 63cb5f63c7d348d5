"""The robot IR (`rbdc-ir-1`, docs/ir.md) as frozen plain-data dataclasses.

The C++ model builder already validated the physics; here we only check shapes and types so that
a malformed file gets an error naming the file, the element and the problem.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace
from typing import Optional, Tuple


FORMAT = "rbdc-ir-1"
ROOT_TYPES = ("floating", "fixed")
JOINT_TYPES = ("revolute", "prismatic")

Vec3 = Tuple[float, float, float]
Mat3 = Tuple[Vec3, Vec3, Vec3]


class IRError(ValueError):
    """Malformed IR; the message names the source, the element and the problem."""


@dataclass(frozen=True)
class Body:
    name: str
    mass: float
    com: Vec3
    inertia_com: Mat3


@dataclass(frozen=True)
class Rotor:
    """A geared rotor carried by the joint's parent, spinning at gear_ratio · q̇ (docs/ir.md)."""
    gear_ratio: float
    mass: float
    inertia: Mat3         # about its origin, rotor axes
    rotation: Mat3        # parent → rotor coordinates
    translation: Vec3     # rotor origin in parent coordinates
    axis: Vec3            # spin axis, rotor coordinates


@dataclass(frozen=True)
class Actuator:
    armature: float
    rotor: Optional[Rotor] = None


@dataclass(frozen=True)
class Joint:
    name: str
    type: str             # floating | fixed (root only), revolute | prismatic
    parent: int           # λ(i); -1 for the root joint
    axis: Vec3
    rotation: Mat3        # E_T: parent → joint coordinates
    translation: Vec3     # r_T: joint origin in parent coordinates
    q_index: int
    v_index: int
    lower: Optional[float]
    upper: Optional[float]
    actuator: Optional[Actuator] = None   # absent on joints without armature or rotor
    angle_offset: float = 0.0  # the traced angle is q + angle_offset (views/turns.py); 0 in every IR


@dataclass(frozen=True)
class Foot:
    name: str
    body: int
    offset: Vec3


@dataclass(frozen=True)
class Frame:
    """An operational frame (docs/model.md, "Frames"): body plus a constant pose."""
    name: str
    body: int
    rotation: Mat3        # E: body → frame coordinates
    translation: Vec3     # frame origin in body coordinates


@dataclass(frozen=True)
class Coupling:
    """A mimic joint: q_follower = multiplier · q_leader + offset (joint indices)."""
    follower: int
    leader: int
    multiplier: float
    offset: float


@dataclass(frozen=True)
class Robot:
    name: str
    floating_base: bool
    gravity: Vec3
    nb: int
    nq: int
    nv: int
    pred: Tuple[int, ...]
    succ: Tuple[int, ...]
    parent: Tuple[int, ...]      # λ over bodies 0 … nb-1 (λ(0) = -1)
    support: Tuple[Tuple[int, ...], ...]   # κ(i)
    children: Tuple[Tuple[int, ...], ...]  # μ(i)
    subtree: Tuple[Tuple[int, ...], ...]   # ν(i)
    bodies: Tuple[Body, ...]
    joints: Tuple[Joint, ...]
    feet: Tuple[Foot, ...]
    couplings: Tuple[Coupling, ...] = ()   # nq, nv and joint indices count only independent ones
    frames: Tuple[Frame, ...] = ()         # operational frames (IR key `frames`; absent: none)

    @property
    def n_joints(self) -> int:
        """Independent 1-DoF joints (the actuated ones): the followers of couplings excluded."""
        return self.nb - 1 - len(self.couplings)

    @property
    def root_dofs(self) -> int:
        return 6 if self.floating_base else 0

    def foot(self, name: str) -> Foot:
        for foot in self.feet:
            if foot.name == name:
                return foot
        raise KeyError(name)


class _Reader:
    """Typed access to the JSON with errors that name the element."""

    def __init__(self, source):
        self.source = source

    def fail(self, where, problem):
        raise IRError("%s: %s: %s" % (self.source, where, problem))

    def get(self, obj, key, where):
        if not isinstance(obj, dict) or key not in obj:
            self.fail(where, "missing key '%s'" % key)
        return obj[key]

    def number(self, x, where):
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            self.fail(where, "expected a number, got %r" % (x,))
        try:
            value = float(x)
        except OverflowError:
            value = math.inf
        if not math.isfinite(value):  # NaN, ±Infinity, or an integer beyond the doubles
            self.fail(where, "expected a finite number, got %r" % (x,))
        return value

    def integer(self, x, where):
        if isinstance(x, bool) or not isinstance(x, int):
            self.fail(where, "expected an integer, got %r" % (x,))
        return x

    def string(self, x, where):
        if not isinstance(x, str):
            self.fail(where, "expected a string, got %r" % (x,))
        if any(c < " " or c == "\x7f" for c in x):  # names reach comments of the generated C++
            self.fail(where, "expected plain text (no control characters), got %r" % (x,))
        return x

    def vec3(self, x, where):
        if not isinstance(x, list) or len(x) != 3:
            self.fail(where, "expected a list of 3 numbers, got %r" % (x,))
        return tuple(self.number(c, where) for c in x)

    def mat3(self, x, where):
        if not isinstance(x, list) or len(x) != 3:
            self.fail(where, "expected a 3x3 list of lists, got %r" % (x,))
        return tuple(self.vec3(row, where) for row in x)

    def int_list(self, x, length, where):
        if not isinstance(x, list) or len(x) != length:
            self.fail(where, "expected a list of %d integers" % length)
        return tuple(self.integer(c, where) for c in x)

    def optional_number(self, x, where):
        return None if x is None else self.number(x, where)


def _actuator(r, raw, where) -> Optional[Actuator]:
    if raw is None:
        return None
    if not isinstance(raw, dict):
        r.fail(where, "expected an object")
    armature = r.number(r.get(raw, "armature", where), where + ".armature")
    if armature < 0:
        r.fail(where + ".armature", "must be ≥ 0, got %r" % armature)
    rotor = None
    if "rotor" in raw:
        o, w = raw["rotor"], where + ".rotor"
        rotor = Rotor(gear_ratio=r.number(r.get(o, "gear_ratio", w), w + ".gear_ratio"),
                      mass=r.number(r.get(o, "mass", w), w + ".mass"),
                      inertia=r.mat3(r.get(o, "inertia", w), w + ".inertia"),
                      rotation=r.mat3(r.get(o, "rotation", w), w + ".rotation"),
                      translation=r.vec3(r.get(o, "translation", w), w + ".translation"),
                      axis=r.vec3(r.get(o, "axis", w), w + ".axis"))
        if rotor.mass < 0:
            r.fail(w + ".mass", "must be ≥ 0, got %r" % rotor.mass)
    return Actuator(armature=armature, rotor=rotor)


def load_ir(source) -> Robot:
    """Reads an IR from a path or an already parsed dict; checks shapes, never physics."""
    if isinstance(source, dict):
        data, name = source, "<ir>"
    else:
        name = str(source)
        try:
            with open(name, encoding="utf-8") as handle:
                data = json.load(handle)
        except OSError as err:
            raise IRError("%s: cannot read: %s" % (name, err.strerror)) from None
        except ValueError as err:  # bad JSON, not UTF-8, an integer of more than 4300 digits
            raise IRError("%s: invalid JSON: %s" % (name, err)) from None
        except RecursionError:
            raise IRError("%s: invalid JSON: nested too deeply" % name) from None
    r = _Reader(name)
    if r.get(data, "format", "top level") != FORMAT:
        r.fail("format", "expected '%s', got %r" % (FORMAT, data.get("format")))
    nb = r.integer(r.get(data, "nb", "top level"), "nb")
    if nb < 1:
        r.fail("nb", "expected at least 1 body")
    floating = r.get(data, "floating_base", "top level")
    if not isinstance(floating, bool):
        r.fail("floating_base", "expected true or false")

    bodies = []
    raw_bodies = r.get(data, "bodies", "top level")
    if not isinstance(raw_bodies, list) or len(raw_bodies) != nb:
        r.fail("bodies", "expected a list of nb = %d bodies" % nb)
    for i, b in enumerate(raw_bodies):
        where = "bodies[%d]" % i
        bodies.append(Body(
            name=r.string(r.get(b, "name", where), where + ".name"),
            mass=r.number(r.get(b, "mass", where), where + ".mass"),
            com=r.vec3(r.get(b, "com", where), where + ".com"),
            inertia_com=r.mat3(r.get(b, "inertia_com", where), where + ".inertia_com")))

    joints = []
    raw_joints = r.get(data, "joints", "top level")
    if not isinstance(raw_joints, list) or len(raw_joints) != nb:
        r.fail("joints", "expected a list of nb = %d joints" % nb)
    for i, j in enumerate(raw_joints):
        where = "joints[%d]" % i
        kind = r.string(r.get(j, "type", where), where + ".type")
        allowed = ROOT_TYPES if i == 0 else JOINT_TYPES
        if kind not in allowed:
            r.fail(where + ".type", "expected one of %s, got '%s'" % (", ".join(allowed), kind))
        parent = r.integer(r.get(j, "parent", where), where + ".parent")
        if (i == 0 and parent != -1) or (i > 0 and not 0 <= parent < i):
            r.fail(where + ".parent", "expected %s, got %d" % ("-1" if i == 0 else "0 ≤ λ(i) < i", parent))
        joints.append(Joint(
            name=r.string(r.get(j, "name", where), where + ".name"),
            type=kind, parent=parent,
            axis=r.vec3(r.get(j, "axis", where), where + ".axis"),
            rotation=r.mat3(r.get(j, "rotation", where), where + ".rotation"),
            translation=r.vec3(r.get(j, "translation", where), where + ".translation"),
            q_index=r.integer(r.get(j, "q_index", where), where + ".q_index"),
            v_index=r.integer(r.get(j, "v_index", where), where + ".v_index"),
            lower=r.optional_number(j.get("lower"), where + ".lower"),
            upper=r.optional_number(j.get("upper"), where + ".upper"),
            actuator=_actuator(r, j.get("actuator"), where + ".actuator")))
    if (joints[0].type == "floating") != floating:
        r.fail("joints[0].type", "'%s' contradicts floating_base = %s" % (joints[0].type, floating))

    root = 6 if floating else 0
    nq = r.integer(r.get(data, "nq", "top level"), "nq")
    nv = r.integer(r.get(data, "nv", "top level"), "nv")
    if nq != nb - 1 + (7 if floating else 0) or nv != nb - 1 + root:
        r.fail("nq/nv", "nq = %d, nv = %d do not match nb = %d" % (nq, nv, nb))
    for i in range(1, nb):
        expected = (i - 1 + (7 if floating else 0), i - 1 + root)
        if (joints[i].q_index, joints[i].v_index) != expected:
            r.fail("joints[%d]" % i, "q_index/v_index must be %d/%d" % expected)

    parent = tuple(j.parent for j in joints)
    lam = r.int_list(r.get(data, "lambda", "top level"), nb - 1, "lambda")
    if lam != parent[1:]:
        r.fail("lambda", "does not match joints[i].parent")
    feet = []
    raw_feet = r.get(data, "feet", "top level")
    if not isinstance(raw_feet, list):
        r.fail("feet", "expected a list")
    for k, f in enumerate(raw_feet):
        where = "feet[%d]" % k
        body = r.integer(r.get(f, "body", where), where + ".body")
        if not 0 <= body < nb:
            r.fail(where + ".body", "body %d out of range 0 … %d" % (body, nb - 1))
        feet.append(Foot(name=r.string(r.get(f, "name", where), where + ".name"), body=body,
                         offset=r.vec3(r.get(f, "offset", where), where + ".offset")))

    frames = []
    raw_frames = data.get("frames", [])
    if not isinstance(raw_frames, list):
        r.fail("frames", "expected a list")
    for k, f in enumerate(raw_frames):
        where = "frames[%d]" % k
        body = r.integer(r.get(f, "body", where), where + ".body")
        if not 0 <= body < nb:
            r.fail(where + ".body", "body %d out of range 0 … %d" % (body, nb - 1))
        frames.append(Frame(name=r.string(r.get(f, "name", where), where + ".name"), body=body,
                            rotation=r.mat3(r.get(f, "rotation", where), where + ".rotation"),
                            translation=r.vec3(r.get(f, "translation", where), where + ".translation")))
    if len({f.name for f in frames}) != len(frames):
        r.fail("frames", "a frame name is used twice")

    def sets(key):
        raw = r.get(data, key, "top level")
        if not isinstance(raw, list) or len(raw) != nb:
            r.fail(key, "expected a list of nb = %d lists" % nb)
        for i, entry in enumerate(raw):
            if not isinstance(entry, list):
                r.fail("%s[%d]" % (key, i), "expected a list of body indices")
        return tuple(tuple(r.integer(x, "%s[%d]" % (key, i)) for x in entry)
                     for i, entry in enumerate(raw))

    couplings = []
    raw_couplings = data.get("couplings", [])
    if not isinstance(raw_couplings, list):
        r.fail("couplings", "expected a list")
    for k, c in enumerate(raw_couplings):
        where = "couplings[%d]" % k
        ends = [r.integer(r.get(c, key, where), "%s.%s" % (where, key)) for key in ("follower", "leader")]
        if not all(1 <= e < nb for e in ends) or ends[0] == ends[1]:
            r.fail(where, "follower and leader must be two joints 1 … %d, got %r" % (nb - 1, ends))
        couplings.append(Coupling(follower=ends[0], leader=ends[1],
                                  multiplier=r.number(r.get(c, "multiplier", where), where + ".multiplier"),
                                  offset=r.number(r.get(c, "offset", where), where + ".offset")))
    followers = {c.follower for c in couplings}
    if len(followers) != len(couplings) or any(c.leader in followers for c in couplings):
        r.fail("couplings", "a joint follows twice, or a leader follows another joint")

    return independent_view(Robot(
        name=r.string(r.get(data, "name", "top level"), "name"),
        floating_base=floating,
        gravity=r.vec3(r.get(data, "gravity", "top level"), "gravity"),
        nb=nb, nq=nq, nv=nv,
        pred=r.int_list(r.get(data, "PRED", "top level"), nb - 1, "PRED"),
        succ=r.int_list(r.get(data, "SUCC", "top level"), nb - 1, "SUCC"),
        parent=parent,
        support=sets("kappa"), children=sets("mu"), subtree=sets("nu"),
        bodies=tuple(bodies), joints=tuple(joints), feet=tuple(feet), couplings=tuple(couplings),
        frames=tuple(frames)))


def independent_view(tree):
    """The robot in independent coordinates; `tree` as the IR describes it (tree indices)."""
    if not tree.couplings:
        return tree
    q0, v0 = (7, 6) if tree.floating_base else (0, 0)
    followers = {c.follower: c for c in tree.couplings}
    index, joints = {}, list(tree.joints)
    for i in range(1, tree.nb):
        if i not in followers:
            index[i] = len(index)
    for i in range(1, tree.nb):
        k = index[followers[i].leader if i in followers else i]
        joints[i] = replace(joints[i], q_index=q0 + k, v_index=v0 + k)
    return replace(tree, nq=q0 + len(index), nv=v0 + len(index), joints=tuple(joints))
