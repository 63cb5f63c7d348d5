"""The looped form of the RNEA's analytic derivatives, for inverse_dynamics_derivatives,
bias_derivatives and gravity_derivatives (docs/performance.md, "The RNEA's derivatives as a loop").

Unrolled, the recursion (algorithms/rnea_derivatives.py) carries each body's rows and columns to every
ancestor by force transforms: O(n·depth) straight-line code (Talos's ∂τ: 1.9 MB of C++, a 100-body
chain's 29 MB), streamed through the instruction cache on every call. In the looped form the traced
part writes each body's transform X_λ(i)^i = (E, r) and gravity in the root's coordinates (O(n)),
and rnea_derivatives_loop (rbdc_gen/rnea_derivatives.hpp) runs the recursion in the root's
coordinates with the tree in a table (body_tree.py): composites are plain sums and each entry one
dot product, as in Pinocchio's world-frame computeRNEADerivatives. It folds nothing (the body
coordinates' sparse axes and constant inertias), so it does more arithmetic than the unrolled
recursion; what it saves is code."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Optional, Tuple

from . import body_tree
from .body_tree import (ACCUMULATE, APPLY, CROSS, SPATIAL_CROSS, STEP_OVERHEAD,
                        ancestor_steps)
from .trace import Argument, with_loop

# The functions with a looped form, and the traced function that writes what the loop reads.
TERMS = {"inverse_dynamics_derivatives": "inverse_dynamics_derivative_transforms",
         "bias_derivatives": "bias_derivative_transforms",
         "gravity_derivatives": "gravity_derivative_transforms"}
HEADER = "rbdc_gen/rnea_derivatives.hpp"
# Past this many (body, ancestor) steps the unrolled recursion is not traced (a 45-body chain;
# Talos has 238): chain100's would be 29 MB of C++ per function, generated in minutes.
UNROLL_LIMIT = 1000
INERTIA_RATE = (43, 38)   # İ = v ×* I − I v×
MASSLESS_ACCUMULATE = (0, 9)
SUBTREE_LANE = (37, 32)   # per descendant of a body: its row's two entries and its column's two
SUBTREE_LANE_AT_REST = (12, 10)  # without velocity: one each
PRODUCT_BLOCK = 8         # the entries run in blocks of 8 descendants (kBlock)


def subtree_lanes(robot):
    """The lanes of the blocks rnea_derivatives_loop runs: for each body j ≥ 1, the blocks of
    PRODUCT_BLOCK bodies (in depth-first order) that cover j and its descendants."""
    ends = body_tree.subtree_ends(body_tree.table_parents(robot))
    return sum(-(-ends[j] // PRODUCT_BLOCK) * PRODUCT_BLOCK - j // PRODUCT_BLOCK * PRODUCT_BLOCK
               for j in range(1, robot.nb))


def _times(piece, n):
    return (piece[0] * n, piece[1] * n)


@dataclass(frozen=True)
class LoopedRneaDerivatives:
    """rnea_derivatives_loop over the robot's bodies, reading the terms' transforms X and gravity g,
    and the function's own v and a (`velocity`, `acceleration`: whether they enter), writing the
    outputs `dq` and `dv` (None: gravity_derivatives has no ∂/∂v)."""
    robot: object
    terms: Tuple[Argument, ...]
    dq: str
    dv: Optional[str]
    velocity: bool
    acceleration: bool
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    def _counts(self):
        """(multiplications, additions) of rnea_derivatives_loop, by trip count."""
        robot, velocity = self.robot, self.velocity
        floating = robot.floating_base
        pieces = body_tree.root_frame_pieces(robot)
        pieces += [(0, 3)] + ([CROSS, (0, 3)] if floating and velocity else [])  # the root's a
        for i in range(1, robot.nb):  # outward: c, then u, v, a
            pieces += [SPATIAL_CROSS]
            pieces += [_times(SPATIAL_CROSS, 2), (12, 18)] if velocity else []
            pieces += [(6, 6)] if self.acceleration else []
        for i in range(0 if floating else 1, robot.nb):  # forces, momenta, rates
            pieces += [APPLY] + ([APPLY, SPATIAL_CROSS, (0, 6), INERTIA_RATE] if velocity else [])
        for i in range(1, robot.nb):  # inward sums
            if floating or robot.parent[i] != 0:
                pieces += [ACCUMULATE, (0, 6)] + ([MASSLESS_ACCUMULATE, (0, 6)] if velocity else [])
        for i in range(1, robot.nb):  # ρ, G, D and the pairs
            pieces += [APPLY, SPATIAL_CROSS, APPLY, (0, 6)]
            if velocity:
                pieces += [APPLY, SPATIAL_CROSS, APPLY, (6, 18), APPLY, SPATIAL_CROSS, (0, 12)]
            if floating:
                pieces += [CROSS] + ([_times(CROSS, 2), (3, 6)] if velocity else [])
        # the entries along each body's subtree, blocks of PRODUCT_BLOCK bodies, padding included
        pieces.append(_times(SUBTREE_LANE if velocity else SUBTREE_LANE_AT_REST, subtree_lanes(robot)))
        if floating:  # the trunk's block
            pieces += [_times(CROSS, 3), _times(APPLY, 3)]
            if velocity:
                pieces += [_times(APPLY, 6), _times(SPATIAL_CROSS, 6), (0, 36),
                           _times(CROSS, 6), (9, 0), _times(APPLY, 3), (0, 18)]
        return sum(m for m, _ in pieces), sum(a for _, a in pieces)

    def operations(self):
        mul, add = self._counts()
        return {"mul": mul, "add": add}

    def instructions(self):
        mul, add = self._counts()
        return max(mul, add) + STEP_OVERHEAD * (ancestor_steps(self.robot) + 2 * self.robot.nb)

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        robot = self.robot
        flags = ", ".join("true" if x else "false" for x in (robot.floating_base, self.velocity, self.acceleration))
        v = "v" if self.velocity else "nullptr"
        a = "a" if self.acceleration else "nullptr"
        return [body_tree.table(robot),
                f"const DenseDerivatives<Scalar, {robot.nv}> out{{{self.dq}, {self.dv or 'nullptr'}}};",
                f"rnea_derivatives_loop<Scalar, {robot.nb}, {robot.nv}, {flags}>(tree, solve_X, solve_g, {v}, {a}, out);"]

    def emission(self, terms_name):
        return ("looped RNEA derivatives: %s writes the %d bodies' transforms and gravity, "
                "rnea_derivatives_loop runs the recursion over a table of the tree (%d body-ancestor steps)"
                % (terms_name, self.robot.nb - 1, ancestor_steps(self.robot)))


def has_looped_form(robot, name):
    return name in TERMS and body_tree.applies(robot)


def unrolled_too_large(robot):
    return ancestor_steps(robot) > UNROLL_LIMIT


def looped_function(robot, scene, name):
    """`name` in its looped form: the traced transforms, with the loop as a LoopedRneaDerivatives."""
    def loop(terms, outputs):
        inputs = {arg.name for arg in terms.inputs}
        return LoopedRneaDerivatives(robot=robot, terms=terms.outputs, dq=outputs[0].name,
                                     dv=outputs[1].name if len(outputs) > 1 else None,
                                     velocity="v" in inputs, acceleration="a" in inputs)
    return with_loop(robot, scene, name, TERMS[name], loop)
