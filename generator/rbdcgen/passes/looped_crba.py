"""The looped form of the CRBA, for mass_matrix, mass_matrix_lower and (under the looped factor) mass_matrix_factor
(docs/performance.md, "The mass matrix as a loop").

Unrolled, the CRBA is one force transform per (body, ancestor) pair: O(n²) straight-line code on a
chain (a 200-body chain: 26 MB of C++, most of the generator's time and more than any compiler takes
in 20 s). In the looped form the traced part writes only each body's transform X_λ(i)^i = (E, r) from
q (O(n), sines and cosines folded with the tree's constant placements), and crba_loop
(rbdc_gen/crba.hpp) runs the recursion with the rest of the tree (parents, axes, inertias) in a table
(body_tree.py). The loop works in the root's coordinates (one transform per body, a dot product per
(body, ancestor) pair, as Pinocchio's crba in the world frame) and folds nothing, so on a small robot
the unrolled CRBA wins by cost; past UNROLL_LIMIT ancestor steps it is not traced at all."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.forward_dynamics import dof_parents, packed_starts
from . import body_tree
from .body_tree import ACCUMULATE, APPLY, PROJECTION, STEP_OVERHEAD, ancestor_steps
from .trace import Argument, with_loop

TERMS = "body_transforms"
HEADER = "rbdc_gen/crba.hpp"
# Past this many (body, ancestor) steps the unrolled CRBA is not traced: a 60-body chain (1 770
# steps) would write ~2.3 MB of mass matrix (chain200: 26 MB for 19 900); humanoid32 has 129, Talos 238.
UNROLL_LIMIT = 1000
PRODUCT_BLOCK = 8          # the products S_jᵀ F_i run in blocks of 8 bodies (kBlock)


def product_lanes(robot):
    """The products S_jᵀ F_i crba_loop computes: for each body j with descendants, the blocks of
    PRODUCT_BLOCK bodies (in depth-first order) that cover them, padding included."""
    lanes = 0
    for j, end in enumerate(body_tree.subtree_ends(body_tree.table_parents(robot))):
        if j and end > j + 1:
            lanes += -(-end // PRODUCT_BLOCK) * PRODUCT_BLOCK - (j + 1) // PRODUCT_BLOCK * PRODUCT_BLOCK
    return lanes


def unrolled_too_large(robot):
    return ancestor_steps(robot) > UNROLL_LIMIT


@dataclass(frozen=True)
class LoopedCrba:
    """crba_loop over the robot's bodies, reading the terms' transforms X, writing M whole
    (`packed` False: the argument M), its lower triangle (`lower`: mass_matrix_lower) or
    ltdl_factor's packed entries (solve_L, solve_D)."""
    robot: object
    terms: Tuple[Argument, ...]
    packed: bool = False
    lower: bool = False
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    @property
    def nb(self):
        return self.robot.nb

    def _counts(self):
        """(multiplications, additions, ancestor steps) of crba_loop, by trip count."""
        robot = self.robot
        pieces = body_tree.root_frame_pieces(robot)
        for i in range(1, robot.nb):
            pieces += [APPLY, PROJECTION, (0, 1)]  # (0, 1): the armature
            pieces += [ACCUMULATE] if robot.parent[i] != 0 or robot.floating_base else []
        pieces += [PROJECTION] * product_lanes(robot)
        return sum(m for m, _ in pieces), sum(a for _, a in pieces), ancestor_steps(robot)

    def operations(self):
        mul, add, _ = self._counts()
        return {"mul": mul, "add": add, "neg": 3 if self.robot.floating_base else 0}

    def instructions(self):
        mul, add, steps = self._counts()
        return max(mul, add) + STEP_OVERHEAD * (steps + self.nb)

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self, with_table=True):
        """The C++ statements; `with_table` False where another loop already declared the tree's table."""
        nv = self.robot.nv
        floating = "true" if self.robot.floating_base else "false"
        if self.packed:
            first = packed_starts(dof_parents(self.robot))[:-1]
            out = [f"RBDC_TABLE int packed_first[{nv}] = {{{', '.join(map(str, first))}}};",
                   f"const PackedMassMatrix<Scalar, {nv}> crba_out{{solve_L, solve_D, packed_first}};"]
        else:
            writer = "LowerMassMatrix" if self.lower else "DenseMassMatrix"
            out = [f"const {writer}<Scalar, {nv}> crba_out{{M}};"]
        return [body_tree.table(self.robot)] * with_table + [*out,
                f"crba_loop<Scalar, {self.nb}, {nv}, {floating}>(tree, solve_X, crba_out);"]

    def emission(self, terms_name):
        return ("looped CRBA: %s writes the %d bodies' transforms, crba_loop runs the recursion over a "
                "table of the tree (%d body-ancestor steps)" % (terms_name, self.nb - 1, ancestor_steps(self.robot)))


def has_looped_form(robot, name):
    """mass_matrix or mass_matrix_lower on a tree without rotors or couplings (both change M beyond the
    bodies' CRBA)."""
    return name in ("mass_matrix", "mass_matrix_lower") and body_tree.applies(robot)


def looped_function(robot, scene, name):
    """mass_matrix or mass_matrix_lower in its looped-CRBA form: the traced transforms, with the loop
    as a LoopedCrba."""
    return with_loop(robot, scene, name, TERMS, lambda terms, _: LoopedCrba(
        robot=robot, terms=terms.outputs, lower=name == "mass_matrix_lower"))
