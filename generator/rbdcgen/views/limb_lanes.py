"""The robot traced in lanes (docs/performance.md, "One SIMD lane per leg", "Limbs in pairs"): the
spine and ONE limb per group of isomorphic limbs (views/limbs.py), the limb's joint variables and
constants holding one value per limb of its group, so that the algorithms of this package, traced
unchanged on this reduced tree, evaluate each group's passes together as lane operations while the
spine stays scalar.

Reduced tree: the spine's bodies and each group's lane limb, in the full robot's order (a quadruped:
body 0 the trunk, bodies 1 … n_limb the lane limb, limb k's l-th body in lane k of body l + 1). The
lane limbs' joints, numbered n = 0, 1, … in that order, have the lane inputs lane_q[n], lane_v[n],
lane_a[n], lane_tau[n] (lane k = the full robot's coordinate of the group's limb k, a pair's limbs
repeated in lanes 2 and 3), their feet the foot forces lane_f; a constant that differs between limbs
is a lane constant (expr.lane_const). Where a limb's wrench or composite inertia joins its spine
body's (into_parent), and where a limb dof updates a spine dof in the LᵀDL factorisation and solve
(into_dof), the group's lanes are summed (a pair's lanes 0 and 1). `scatter` and `scatter_matrix`
map the reduced outputs back to the full robot's coordinates."""

from __future__ import annotations

import os
from dataclasses import dataclass, replace

from ..graph import expr as ex
from ..graph import spatial as sp
from . import regrouped
from .limbs import LimbError
from ..algorithms import forward_dynamics as fd
from .scalar import TracedModel


@dataclass(frozen=True)
class LaneLayout:
    """What the emitter needs of a lane function: the values of its lane symbols."""
    constants: tuple   # lane constant c (symbol lane_c[c]): one float per lane
    inputs: dict       # "lane_q" / "lane_v" / "lane_a" → per lane joint l, the (array, index) per lane
    angle_names: dict  # ("lane_q", l) → the identifier its sin/cos are named by

    def distinct_lanes(self, array, index):
        """How many lanes of lane input array[index] hold values of their own: all ex.LANES, or the
        2 (1) of a smaller group repeated to fill them (only those need their own sin and cos)."""
        sources = self.inputs[array][index]
        return next(u for u in (1, 2, ex.LANES) if all(s == sources[k % u] for k, s in enumerate(sources)))

    def with_lanes(self, inputs):
        """Inputs {array: floats} of the full robot with the lane arrays added (expr.evaluate)."""
        lanes = {name: [tuple(inputs[array][index] for array, index in sources) for sources in joints]
                 for name, joints in self.inputs.items() if all(s[0] in inputs for s in joints[0])}
        return {**inputs, **lanes, ex.LANE_CONSTANTS: list(self.constants)}


class LaneModel(TracedModel):
    """TracedModel of the reduced tree: `robot` is the spine and the groups' lane limbs, `full` the
    robot. With `feet`, the scene's feet on the limbs become lane feet (the same number on each limb
    of a group, at the same bodies of the limb) with the lane input lane_f, those on the spine stay
    scalar feet with their input f; without, the traced function uses no feet. Frames, contacts and
    the solves of limb columns need the quadruped's one group of the trunk (limbs). With
    `pair_streams`, a pair's spare lanes may carry a second quantity (spare_lanes)."""

    def __init__(self, robot, scene, groups, zero_inputs=(), feet=False, frames=False, pair_streams=False):
        super().__init__(robot, scene, zero_inputs)
        self.pair_streams = pair_streams  # spare_lanes
        self.full = self.robot
        self.groups = groups
        self.limbs = groups[0].lanes
        self.frame_places = ()
        if frames:
            self.frames, self.frame_places = lane_frames(self.frames, self.limbs)
        else:
            self.frames = ()
        self.graph = ex.current_graph()  # holds the lane constants' values
        # per reduced body: the full robot's body in each lane, and its group (None: the spine)
        self._lanes_in, self._group = _reduced_bodies(self.full, groups)
        self.robot = _reduced_tree(self.full, self._lanes_in, self._group, groups)
        lane_bodies = [i for i in range(1, self.robot.nb) if self._group[i] is not None]
        self._lane_number = {i: n for n, i in enumerate(lane_bodies)}
        # lane_x[n] in lane k is the full robot's input x at the joint of lane body n's lane k: (array,
        # index) per lane.
        self.lane_inputs = {
            "lane_" + name: [tuple((name, index(self.full.joints[b])) for b in self._lanes_in[i])
                             for i in lane_bodies]
            for name, index in (("q", lambda j: j.q_index), ("v", lambda j: j.v_index),
                                ("a", lambda j: j.v_index),
                                ("tau", lambda j: j.v_index - self.full.root_dofs))}
        self.kept_feet = self.feet  # the full robot's
        self.feet, self._foot_forces = self._lane_feet() if feet else ((), ())

    def layout(self):
        names = {}
        for i, n in self._lane_number.items():
            name = _shared_name([self.full.joints[b].name for b in self._live_bodies(i)])
            if not name or "lanes_" + name in names.values():
                name = "joint_%d" % i  # the limbs' joint names share nothing that tells them apart
            names[("lane_q", n)] = "lanes_" + name
        return LaneLayout(tuple(self.graph.lane_constants), self.lane_inputs, names)

    # --- lane values --------------------------------------------------------------------------
    def _lane_feet(self):
        """The scene's feet on the reduced tree and where each one's force is (array, first entry): a
        spine foot as it is (input f), a group's feet as lane feet (input lane_f); per kept foot its
        place (traced foot n, lane k) in foot_places."""
        kept = list(self.feet)
        reduced = {lanes[0]: i for i, lanes in enumerate(self._lanes_in)}
        feet, forces, places, self._foot_group = [], [], {}, []
        for f, foot in enumerate(kept):
            if foot.body in reduced and self._group[reduced[foot.body]] is None:
                places[f] = (len(feet), 0)
                feet.append(replace(foot, body=reduced[foot.body]))
                forces.append(("f", 3 * f))
                self._foot_group.append(None)
        self.lane_inputs["lane_f"] = []
        for g, group in enumerate(self.groups):
            in_group = [f for f, foot in enumerate(kept) if any(foot.body in limb for limb in group.limbs)]
            if not in_group:
                continue
            per_limb, shape = feet_shape(self.full.name, [kept[f] for f in in_group], group.limbs)
            per_lane = [[in_group[n] for n in per_limb[k % len(per_limb)]] for k in range(ex.LANES)]
            for k in group.live:
                for n, f in enumerate(per_lane[k]):
                    places[f] = (len(feet) + n, k)
            for n, l in enumerate(shape):
                lanes = [kept[feet_k[n]] for feet_k in per_lane]
                offset = tuple(ex.lane_const([foot.offset[c] for foot in lanes]) for c in range(3))
                feet.append(replace(lanes[0], name="/".join(foot.name for foot in lanes[:len(group.limbs)]),
                                    body=reduced[group.limbs[0][l]], offset=offset))
                first = len(self.lane_inputs["lane_f"])
                self.lane_inputs["lane_f"] += [tuple(("f", 3 * feet_k[n] + c) for feet_k in per_lane)
                                               for c in range(3)]
                forces.append(("lane_f", first))
                self._foot_group.append(g)
        self.foot_places = tuple(places[f] for f in range(len(kept)))
        return tuple(feet), tuple(forces)

    @property
    def tau(self):
        return tuple(self._lane_input("tau", i) if self._group[i] is not None
                     else self.input("tau", self.coupled.n_joints)[self._full_joint(i).v_index - self.full.root_dofs]
                     for i in range(1, self.robot.nb))

    def foot_force(self, k):
        if "f" in self.zero_inputs:
            return sp.zeros(3)
        array, first = self._foot_forces[k]
        if array == "f":
            return tuple(self.input("f", 3 * len(self.kept_feet))[first:first + 3])
        return tuple(ex.symbol(array, first + c) for c in range(3))

    def into_dof(self, k, i, value):
        """A limb dof's term in a spine dof's entry (LᵀDL factorisation and solve): summed over its
        group's lanes."""
        limb, spine = self._dof_group(k), self._dof_group(i)
        return _sum_lanes(value, self.groups[limb]) if limb is not None and spine is None else value

    def into_spine(self, k, row, col, term):
        group = self._foot_group[k]
        if group is None or self._dof_group(row) is not None or self._dof_group(col) is not None:
            return term
        return _sum_lanes(term, self.groups[group])

    def into_root(self, term):
        return ex.lane_sum(term)

    def _lane_input(self, name, i):
        return ex.const(0.0) if name in self.zero_inputs else ex.symbol("lane_" + name, self._lane_number[i])

    def _lanes_of(self, i):
        """The full robot's bodies in the lanes of reduced body i ≥ 1."""
        return list(self._lanes_in[i])

    def _live_bodies(self, i):
        """The full robot's bodies of reduced body i's own lanes (a pair's two limbs, not repeated)."""
        group = self._group[i]
        return self._lanes_in[i][:1] if group is None else self._lanes_in[i][:len(self.groups[group].limbs)]

    def _full_joint(self, i):
        """The full robot's joint of spine body i."""
        return self.full.joints[self._lanes_in[i][0]]

    def _dof_group(self, x):
        """The group of the reduced tree's dof x (None: a root or spine dof)."""
        root = self.robot.root_dofs
        return None if x < root else self._group[x - root + 1]

    def _live(self, x):
        """The lanes of dof x that hold the full robot's values (lane 0 alone for a spine dof)."""
        group = self._dof_group(x)
        return range(1) if group is None else self.groups[group].live

    # --- the reduced tree's joints and bodies ------------------------------------------------
    def qi(self, i):
        return self._lane_input("q", i) if self._group[i] is not None else self.q[self._full_joint(i).q_index]

    def vi(self, i):
        return self._lane_input("v", i) if self._group[i] is not None else self.v[self._full_joint(i).v_index]

    @property
    def tree_velocity(self):
        return tuple(self.v[:self.robot.root_dofs]) + tuple(self.vi(i) for i in range(1, self.robot.nb))

    @property
    def tree_acceleration(self):
        return tuple(self.a[:self.robot.root_dofs]) + tuple(self.ai(i) for i in range(1, self.robot.nb))

    def ai(self, i):
        return self._lane_input("a", i) if self._group[i] is not None else self.a[self._full_joint(i).v_index]

    def angle_offset(self, i):
        """A lane limb's offsets (views/turns.py) as a lane constant, which joint_sincos's array adds
        lane by lane (backend/emit.py)."""
        if self._group[i] is None:
            return super().angle_offset(i)
        return ex.lane_const([self.full.joints[b].angle_offset for b in self._lanes_of(i)])

    def X_tree(self, i):
        """X_T of joint i: a lane limb's with each entry a lane constant."""
        if self._group[i] is None:
            return super().X_tree(i)
        joints = [self.full.joints[b] for b in self._lanes_of(i)]
        rotations = [sp.snap_rotation(j.rotation) for j in joints]
        identity = all(r[a][b] == (1.0 if a == b else 0.0)
                       for r in rotations for a in range(3) for b in range(3))
        E_T = tuple(tuple(ex.lane_const([r[a][b] for r in rotations]) for b in range(3))
                    for a in range(3))
        r_T = tuple(ex.lane_const([j.translation[a] for j in joints]) for a in range(3))
        return sp.Transform(None if identity else E_T,
                            r_T if any(any(j.translation) for j in joints) else None)

    def body_parameters(self):
        """The full robot's regrouped parameters (views/regrouped.py) of each reduced body's lane 0:
        a spine body's own."""
        if "parameters" not in self._cache:
            full = regrouped.body_parameters(self.full)
            self._cache["parameters"] = tuple(full[lanes[0]] for lanes in self._lanes_in)
        return self._cache["parameters"]

    def inertia(self, i):
        if self._group[i] is None:
            return super().inertia(i)
        key = ("inertia", i)
        if key not in self._cache:
            parameters = regrouped.body_parameters(self.full)
            lanes = [sp.Inertia.of(*parameters[b]) for b in self._lanes_of(i)]
            m = ex.lane_const([x.m.value for x in lanes])
            h = tuple(ex.lane_const([x.h[a].value for x in lanes]) for a in range(3))
            ibar = tuple(tuple(ex.lane_const([x.Ibar[a][b].value for x in lanes]) for b in range(3))
                         for a in range(3))
            self._cache[key] = sp.Inertia(m, h, sp.symmetric(ibar))
        return self._cache[key]

    def rotor(self, i):
        return None if self._group[i] is not None else super().rotor(i)  # limbs have no rotors

    def armature(self, i):
        if self._group[i] is None:
            return super().armature(i)
        values = [0.0 if j.actuator is None else j.actuator.armature
                  for j in (self.full.joints[b] for b in self._lanes_of(i))]
        return values[0] if all(v == values[0] for v in values) else ex.lane_const(values)

    def into_parent(self, i, value):
        """A limb's wrench or composite inertia joins its spine body's as the sum of its group's lanes."""
        group = self._group[i]
        if group is None or self._group[self.robot.parent[i]] is not None:
            return value
        return _sum_lanes(value, self.groups[group])

    def spare_lanes(self, i):
        group = self._group[i]
        return self.pair_streams and group is not None and self.groups[group].spare_lanes

    # --- outputs --------------------------------------------------------------------------------
    def full_index(self, x, lane):
        """The full robot's dof of the reduced tree's dof x in lane `lane` (root dofs are shared)."""
        root = self.robot.root_dofs
        return x if x < root else self.full.joints[self._lanes_in[x - root + 1][lane]].v_index

    def foot_force_index(self, row, lane):
        """The full robot's entry of f (column-major 3 × n_feet) in lane `lane` of lane_f[row]."""
        return self.lane_inputs["lane_f"][row][lane][1]

    def solve_limb_column(self, L, inv_diag, parents, b):
        """M⁻¹ b (forward_dynamics.ltdl_solve, L and D of the reduced tree) for a right-hand side b
        whose lane k stands for a column of limb k: non-zero in the trunk rows and limb k's rows
        only. Returns per lane k the solution of limb k's column (substitute_limb_columns). The
        leaves-to-root pass runs with the columns in lanes (no lane sum: only limb k's rows reach
        lane k's trunk entries)."""
        return self.substitute_limb_columns(L, parents, fd.ltdl_eliminate(L, inv_diag, parents, b))

    def substitute_limb_columns(self, L, parents, y):
        """The root-to-leaves pass x = L⁻¹y of M⁻¹'s solve for y = D⁻¹L⁻ᵀb of limb columns (lane k:
        limb k's column): per lane k the solution of that column, a reduced vector (scatter) with
        scalar trunk entries and limb m's entries in lane m: the solution is dense, every limb moves
        with the trunk. The trunk's rows run with the columns in lanes; then, per lane k, the
        trunk's solution of that column leaves its lane (lane_get) and the limbs' rows run in lanes,
        limb k's own part of y masked to lane k."""
        root = self.robot.root_dofs
        trunk = fd.ltdl_substitute(L, parents, y[:root], range(root))
        solutions = []
        for k in range(ex.LANES):
            mask = ex.lane_const([1.0 if lane == k else 0.0 for lane in range(ex.LANES)])
            x = [ex.lane_get(t, k) for t in trunk] + [value * mask for value in y[root:]]
            solutions.append(fd.ltdl_substitute(L, parents, x, range(root, len(x))))
        return solutions

    def scatter(self, reduced):
        """A joint-space vector of the reduced tree as the full robot's: lane k of the lane limb's
        joint l goes to limb k's joint l."""
        full = [None] * self.full.nv
        for x, value in enumerate(reduced):
            for k in self._live(x):
                full[self.full_index(x, k)] = ex.lane_get(value, k)
        return tuple(full)

    def scatter_bodies(self, values):
        """Per reduced body i ≥ 1 its values (values[i], a tuple) as per full robot body: lane k of a
        lane body's values for the full robot's body in lane k, a spine body's as they are."""
        full = [None] * self.full.nb
        for i in range(1, self.robot.nb):
            for k, body in enumerate(self._live_bodies(i)):
                full[body] = tuple(ex.lane_get(x, k) for x in values[i])
        return full

    def feet_values(self, values):
        """Per lane foot values as the kept feet's: lane k of lane foot n for the foot on limb k."""
        return _places(values, self.foot_places)

    def frame_values(self, values):
        """Per reduced frame values as the scene's frames': lane k of reduced frame n for the frame
        on limb k (a trunk frame's value is no lane value: as it is)."""
        return _places(values, self.frame_places)

    def frame_rows(self, rows):
        """Rows of 6 per reduced frame (columns: the reduced tree's dofs) as the scene's frames'
        rows over the full robot's dofs: lane k for the frame on limb k, limb k's joint columns
        from the lane limb's, the other limbs' zero (a trunk frame's joint columns are zeros)."""
        return self.place_rows(rows, self.frame_places, 6)

    def place_rows(self, rows, places, per_place):
        """Rows over the reduced tree's dofs, `per_place` of them per reduced place n, as rows over the
        full robot's dofs, one block per (n, lane k) of `places`: lane k, limb k's joint columns
        from the lane limb's, the other limbs' zero."""
        full = []
        for n, k in places:
            for r in range(per_place):
                out = [ex.const(0.0)] * self.full.nv
                for x, value in enumerate(rows[per_place * n + r]):
                    out[self.full_index(x, k)] = ex.lane_get(value, k)
                full.append(tuple(out))
        return tuple(full)

    def scatter_joint_columns(self, rows):
        """A matrix (rows) whose columns are the reduced tree's joints as the full robot's: lane k of
        the lane limb's joint l goes to limb k's joint l's column."""
        root = 6 if self.full.floating_base else 0
        full = [[None] * self.full.n_joints for _ in rows]
        for r, row in enumerate(rows):
            for c, value in enumerate(row):
                for k in range(ex.LANES):
                    full[r][self.full_index(root + c, k) - root] = ex.lane_get(value, k)
        return tuple(tuple(row) for row in full)

    def scatter_matrix(self, reduced):
        """A joint-space matrix (rows) of the reduced tree as the full robot's; entries between two
        different limbs are zero (no body of one limb moves with the other's joints)."""
        full = [[ex.const(0.0)] * self.full.nv for _ in range(self.full.nv)]
        for r, row in enumerate(reduced):
            for c, value in enumerate(row):
                for k in self._shared_lanes(r, c):
                    full[self.full_index(r, k)][self.full_index(c, k)] = ex.lane_get(value, k)
        return full

    def _shared_lanes(self, r, c):
        """The lanes whose entry (r, c) is the full robot's: none between two groups' limbs (they
        share no motion), the live lanes of the group of r or c, lane 0 between spine dofs."""
        groups = {self._dof_group(r), self._dof_group(c)} - {None}
        return () if len(groups) > 1 else self._live(r if self._dof_group(r) is not None else c)


def lane_column_order(robot, limbs, column_dofs):
    """Where the looped solve keeps right-hand-side columns (the logical column at each place) so
    that lane function terms store whole lane values: `column_dofs` per block (q, v, τ, ...) the dof
    of each column. Each block's limb columns come first, one limb dof at a time in lane order (limb
    k's at k: a trunk row's derivatives along the four limbs are one lane value), every block's other
    columns after them; the blocks' limb columns are multiples of ex.LANES, so every lane group starts
    a vector run. Without it, the Mini Cheetah's contact terms gathered 114 of their 216 stores of r₁
    from lanes of different values (docs/performance.md)."""
    place = {robot.joints[body].v_index: (l, k) for k, limb in enumerate(limbs) for l, body in enumerate(limb)}
    limb_part, other_part, first = [], [], 0
    for dofs in column_dofs:
        columns = range(first, first + len(dofs))
        limb_part += sorted((c for c in columns if dofs[c - first] in place), key=lambda c: place[dofs[c - first]])
        other_part += [c for c in columns if dofs[c - first] not in place]
        first += len(dofs)
    return tuple(limb_part + other_part)


def feet_shape(robot_name, kept, limbs):
    """Per limb the indices of the kept feet on it, and the limb bodies they sit on (the same on
    every limb, else LimbError)."""
    per_limb = [[k for k, foot in enumerate(kept) if foot.body in limb] for limb in limbs]
    shapes = {tuple(limb.index(kept[k].body) for k in feet) for limb, feet in zip(limbs, per_limb)}
    if len(shapes) != 1 or sum(map(len, per_limb)) != len(kept):
        raise LimbError("robot '%s': the kept feet are not the same on every limb" % robot_name)
    return per_limb, next(iter(shapes))


def contact_lanes(feet, contacts, limbs):
    """The lane of each contact foot, when each limb carries exactly one of the kept feet (the lane
    foot of contact dynamics on the lane model) and at most one contact, else LimbError."""
    limb_of = {body: k for k, limb in enumerate(limbs) for body in limb}
    if sorted(limb_of.get(foot.body, -1) for foot in feet) != list(range(len(limbs))):
        raise LimbError("the kept feet are not one per limb")
    lanes = tuple(limb_of[foot.body] for foot in contacts)
    if len(set(lanes)) != len(lanes):  # a foot listed twice: its two contacts share the limb's dofs
        raise LimbError("a limb has two contacts")
    return lanes


def frame_shapes(frames, limbs):
    """The scene's frames split into those on the trunk and, per limb, those on it (ordered by limb
    body and rotation), if every limb carries the same frames (at the same limb bodies, with the same
    rotations), else LimbError."""
    limb_of = {body: (k, l) for k, limb in enumerate(limbs) for l, body in enumerate(limb)}

    def place(f):
        return limb_of[f.body][1], sp.snap_rotation(f.rotation)

    # each limb's frames by limb body and rotation (stable: frames at one place pair in scene order)
    per_limb = [sorted((f for f in frames if f.body in limb_of and limb_of[f.body][0] == k), key=place)
                for k in range(len(limbs))]
    shapes = {tuple(place(f) for f in fs) for fs in per_limb}
    if len(shapes) != 1:
        raise LimbError("the scene's frames are not the same on every limb")
    return [f for f in frames if f.body == 0], per_limb, next(iter(shapes))


def lane_frames(frames, limbs):
    """The scene's frames on the reduced tree: those on the trunk as they are, those on the limbs
    as lane frames (frame_shapes; the translation a lane constant). Also, per scene frame, its
    place (n, k): reduced frame n (trunk frames first), lane k (0 for a trunk frame)."""
    trunk, per_limb, shape = frame_shapes(frames, limbs)
    reduced = list(trunk)
    for n, (l, rotation) in enumerate(shape):
        lanes = [fs[n] for fs in per_limb]
        translation = tuple(ex.lane_const([f.translation[c] for f in lanes]) for c in range(3))
        reduced.append(replace(lanes[0], name="/".join(f.name for f in lanes), body=l + 1,
                               rotation=rotation, translation=translation))
    lane_of = {f.name: (len(trunk) + n, k) for k, fs in enumerate(per_limb) for n, f in enumerate(fs)}
    places = tuple((trunk.index(f), 0) if f.body == 0 else lane_of[f.name] for f in frames)
    return tuple(reduced), places


def _places(values, places):
    """Lane k of values[n] for each place (n, k)."""
    return [_lane_part(values[n], k) for n, k in places]


def _lane_part(value, lane):
    """Lane `lane` of a value, a vector or matrix (nested tuples)."""
    if isinstance(value, (tuple, list)):
        return tuple(_lane_part(x, lane) for x in value)
    return ex.lane_get(value, lane)


def _sum_lanes(value, group):
    """The sum over a group's limbs of a value, a vector or matrix (nested tuples) or a spatial
    inertia: all lanes, or those of a group of fewer limbs (a pair's lanes 0 and 1)."""
    if isinstance(value, sp.Inertia):
        return sp.Inertia(_sum_lanes(value.m, group), _sum_lanes(value.h, group),
                          sp.symmetric(tuple(_sum_lanes(row, group) for row in value.Ibar)))
    if isinstance(value, tuple):
        return tuple(_sum_lanes(x, group) for x in value)
    if len(group.limbs) == ex.LANES:
        return ex.lane_sum(value)
    total = ex.lane_get(value, 0)
    for k in group.live[1:]:
        total = total + ex.lane_get(value, k)
    return total


def _reduced_bodies(robot, groups):
    """Per body of the reduced tree, the full robot's bodies in its lanes (a spine body: itself in
    every lane), and its group's index (None: the spine), in the full robot's order: the spine and
    each group's limb 0."""
    lanes_of = {}
    for g, group in enumerate(groups):
        for l, body in enumerate(group.limbs[0]):
            lanes_of[body] = (tuple(limb[l] for limb in group.lanes), g)
    in_limbs = {body for group in groups for limb in group.limbs for body in limb}
    kept = [b for b in range(robot.nb) if b in lanes_of or b not in in_limbs]
    return (tuple(lanes_of[b][0] if b in lanes_of else (b,) * ex.LANES for b in kept),
            tuple(lanes_of[b][1] if b in lanes_of else None for b in kept))


def _reduced_tree(robot, lanes_in, group, groups):
    """The reduced bodies (lanes_in, group: _reduced_bodies) renumbered 0 … n (rbdc order kept);
    joints keep their types and axes (a limb's: limb 0's), their q and v indices count in the
    reduced tree; a limb body's name joins its group's limbs' names."""
    first = [lanes[0] for lanes in lanes_in]
    number = {body: i for i, body in enumerate(first)}
    root_q, root_v = (7, 6) if robot.floating_base else (0, 0)
    parent = (-1,) + tuple(number[robot.parent[b]] for b in first[1:])
    nb = len(parent)
    children = tuple(tuple(c for c in range(1, nb) if parent[c] == i) for i in range(nb))
    subtree = tuple(tuple(c for c in range(i, nb) if _is_ancestor(parent, i, c)) for i in range(nb))
    support = tuple(tuple(a for a in range(1, nb) if _is_ancestor(parent, a, i)) for i in range(nb))

    def name(items, i):
        live = 1 if group[i] is None else len(groups[group[i]].limbs)
        return "/".join(items[b].name for b in lanes_in[i][:live])

    bodies = (robot.bodies[0],) + tuple(replace(robot.bodies[b], name=name(robot.bodies, i))
                                        for i, b in enumerate(first) if i > 0)
    joints = (robot.joints[0],) + tuple(
        replace(robot.joints[b], name=name(robot.joints, i), parent=parent[i],
                q_index=root_q + i - 1, v_index=root_v + i - 1)
        for i, b in enumerate(first) if i > 0)
    return replace(robot, nb=nb, nq=root_q + nb - 1, nv=root_v + nb - 1,
                   pred=tuple(parent[1:]), succ=tuple(range(1, nb)), parent=parent,
                   support=support, children=children, subtree=subtree, bodies=bodies,
                   joints=joints, feet=(), couplings=())


def _shared_name(names):
    """What the lanes' joint names have in common: their common prefix and suffix joined
    (abduct_fr_to_thigh_fr_j, abduct_hl_to_thigh_hl_j -> abduct_j), '' when they share nothing."""
    prefix = os.path.commonprefix(names)
    suffix = os.path.commonprefix([n[len(prefix):][::-1] for n in names])[::-1]
    return "_".join(part.strip("_") for part in (prefix, suffix) if part.strip("_"))


def _is_ancestor(parent, a, i):
    """Whether a is i or on its path to the root."""
    while i > 0 and i != a:
        i = parent[i]
    return i == a
