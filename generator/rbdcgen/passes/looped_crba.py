"""The looped form of the CRBA, for mass_matrix and (under the looped factor) mass_matrix_factor
(docs/performance.md, "The mass matrix as a loop").

Unrolled, the CRBA is one force transform per (body, ancestor) pair: O(n²) straight-line code on a
chain (a 200-body chain: 26 MB of C++, most of the generator's time and more than any compiler takes
in 20 s). In the looped form the traced part writes only each body's transform X_λ(i)^i = (E, r) from
q (O(n), sines and cosines folded with the tree's constant placements), and crba_loop
(rbdc_gen/crba.hpp) runs the recursion with the rest of the tree (parents, axes, inertias) in a table.
The loop works in the root's coordinates (one transform per body, a dot product per (body,
ancestor) pair, as Pinocchio's crba in the world frame) and folds nothing, so on a small robot the
unrolled CRBA wins by cost; past UNROLL_LIMIT ancestor steps it is not traced at all."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import ClassVar, Tuple

from ..algorithms.crba import depth_first_order
from ..algorithms.forward_dynamics import dof_parents, packed_starts
from ..graph.spatial import inertia_at_origin, snap_axis
from .trace import Argument, signature, trace_function

TERMS = "body_transforms"
HEADER = "rbdc_gen/crba.hpp"
# Past this many (body, ancestor) steps the unrolled CRBA is not traced: a 60-body chain (1 770
# steps) would write ~2.3 MB of mass matrix (chain200: 26 MB for 19 900); humanoid32 has 129, Talos 238.
UNROLL_LIMIT = 1000
# crba_loop's arithmetic (rbdc_gen/crba.hpp), per call of each piece: (multiplications, additions).
ROOT_TRANSFORM = (36, 27)  # X_0^i = X_i X_0^λ(i), below the root's children
AXIS = (9, 6)              # the joint axis in root coordinates
REVOLUTE_SUBSPACE = (6, 3)  # S = (z; p × z)
CONGRUENCE = (75, 59)      # the body's inertia in root coordinates
ACCUMULATE = (0, 10)       # into the parent's composite inertia
APPLY = (24, 18)           # F = I_c S
PROJECTION = (6, 5)        # Sᵀ F
PRODUCT_BLOCK = 8          # the products S_jᵀ F_i run in blocks of 8 bodies (kBlock)
# Instructions the cost model counts per ancestor step and per body besides the arithmetic (the
# walk, the table, the stores); the arithmetic itself as max(multiplications, additions): fused.
STEP_OVERHEAD = 4


def ancestor_steps(robot):
    """(body, ancestor body) pairs with a joint: the force transforms of the unrolled CRBA."""
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


def product_lanes(robot):
    """The products S_jᵀ F_i crba_loop computes: for each body j with descendants, the blocks of
    PRODUCT_BLOCK bodies (in depth-first order) that cover them, padding included."""
    parents = _table_parents(robot)
    lanes = 0
    for j, end in enumerate(subtree_ends(parents)):
        if j and end > j + 1:
            lanes += -(-end // PRODUCT_BLOCK) * PRODUCT_BLOCK - (j + 1) // PRODUCT_BLOCK * PRODUCT_BLOCK
    return lanes


def _table_parents(robot):
    """The parents in depth-first order (crba.depth_first_order), as the table holds them."""
    order = depth_first_order(robot)
    position = {body: k for k, body in enumerate(order)}
    return [position[robot.parent[i]] if i else -1 for i in order]


def unrolled_too_large(robot):
    return ancestor_steps(robot) > UNROLL_LIMIT


def _upper(matrix):
    return [matrix[0][0], matrix[0][1], matrix[0][2], matrix[1][1], matrix[1][2], matrix[2][2]]


@dataclass(frozen=True)
class LoopedCrba:
    """crba_loop over the robot's bodies, reading the terms' transforms X, writing M whole
    (`packed` False: the argument M) or ltdl_factor's packed entries (solve_L, solve_D)."""
    robot: object
    terms: Tuple[Argument, ...]
    packed: bool = False
    headers: ClassVar[Tuple[str, ...]] = (HEADER,)

    @property
    def nb(self):
        return self.robot.nb

    def _counts(self):
        """(multiplications, additions, ancestor steps) of crba_loop, by trip count."""
        robot = self.robot
        pieces = []
        for i in range(1, robot.nb):
            below_root = robot.parent[i] != 0
            pieces += [AXIS, CONGRUENCE, APPLY, PROJECTION, (0, 1)]  # (0, 1): the armature
            pieces += [ROOT_TRANSFORM] if below_root else []
            pieces += [REVOLUTE_SUBSPACE] if robot.joints[i].type == "revolute" else []
            pieces += [ACCUMULATE] if below_root or robot.floating_base else []
        steps = ancestor_steps(robot)
        pieces += [PROJECTION] * product_lanes(robot)
        return sum(m for m, _ in pieces), sum(a for _, a in pieces), steps

    def operations(self):
        mul, add, _ = self._counts()
        return {"mul": mul, "add": add, "neg": 3 if self.robot.floating_base else 0}

    def instructions(self):
        mul, add, steps = self._counts()
        return max(mul, add) + STEP_OVERHEAD * (steps + self.nb)

    def table(self):
        """The tree's constants as a CrbaTree initialiser, the bodies in depth-first order (the
        order of the terms' transforms)."""
        robot = self.robot
        order = depth_first_order(robot)
        parents = _table_parents(robot)

        def row(values):
            return "{" + ", ".join(values) + "}"

        def number(x):
            return repr(float(x))

        joints = [robot.joints[i] for i in order]
        bodies = [robot.bodies[i] for i in order]
        no_axis = [0.0, 0.0, 0.0]  # the root's
        fields = [
            row(map(str, parents)),
            row(map(str, subtree_ends(parents))),
            row(str(joint.v_index if k else -1) for k, joint in enumerate(joints)),
            row("true" if k and joint.type == "revolute" else "false" for k, joint in enumerate(joints)),
            row(row(number(x) for x in (snap_axis(joint.axis) if k else no_axis)) for k, joint in enumerate(joints)),
            row(number(body.mass) for body in bodies),
            row(row(number(body.mass * c) for c in body.com) for body in bodies),
            row(row(number(x) for x in _upper(inertia_at_origin(body))) for body in bodies),
            row(number(joint.actuator.armature if k and joint.actuator else 0.0) for k, joint in enumerate(joints))]
        return f"const CrbaTree<{robot.nb}> crba_tree{{{', '.join(fields)}}};"

    def loops(self):
        nv = self.robot.nv
        floating = "true" if self.robot.floating_base else "false"
        if self.packed:
            first = packed_starts(dof_parents(self.robot))[:-1]
            out = [f"const int packed_first[{nv}] = {{{', '.join(map(str, first))}}};",
                   f"const PackedMassMatrix<Scalar, {nv}> crba_out{{solve_L, solve_D, packed_first}};"]
        else:
            out = [f"const DenseMassMatrix<Scalar, {nv}> crba_out{{M}};"]
        return [self.table(), *out,
                f"crba_loop<Scalar, {self.nb}, {nv}, {floating}>(crba_tree, solve_X, crba_out);"]

    def emission(self, terms_name):
        return ("looped CRBA: %s writes the %d bodies' transforms, crba_loop runs the recursion over a "
                "table of the tree (%d body-ancestor steps)" % (terms_name, self.nb - 1, ancestor_steps(self.robot)))



def has_looped_form(robot, name):
    """mass_matrix on a tree without rotors or couplings (both change M beyond the bodies' CRBA)."""
    return (name == "mass_matrix" and robot.nb > 1 and not robot.couplings
            and not any(j.actuator is not None and j.actuator.rotor is not None for j in robot.joints))


def looped_function(robot, scene, name):
    """mass_matrix in its looped-CRBA form: the traced transforms, with the loop as a LoopedCrba."""
    doc, inputs, outputs = signature(robot, scene, name)
    terms = trace_function(robot, scene, TERMS)
    assert terms.inputs == inputs
    return replace(terms, name=name, doc=doc, outputs=outputs, computes=name,
                   solve=LoopedCrba(robot=robot, terms=terms.outputs))
