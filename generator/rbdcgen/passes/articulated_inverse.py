"""M⁻¹ of a fixed-base chain by the articulated-body recursion (rbdc_gen::articulated_inverse), for
forward_dynamics_derivatives' low-rank form (looped_solve.low_rank_applies; docs/performance.md, "M⁻¹ by
the articulated-body recursion"): the ABA run for every unit torque at once, O(n²) multiply-adds on a
chain, where the looped CRBA, the factor M = Lᵀ D L and Zᵀ D⁻¹ Z (looped_inverse.py) take O(n³)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from . import body_tree
from .body_tree import ACCUMULATE, APPLY, PROJECTION, STEP_OVERHEAD

HEADER = "rbdc_gen/articulated_inverse.hpp"
SYMMETRIC_APPLY = (36, 30)  # P S, P a symmetric 6 × 6
OUTER = (21, 21)            # P + U wᵀ, its upper triangle
BELOW = (13, 11)            # a column below the body, leaves first: Sᵀ p^A, D⁻¹ u, p^A + U m
FORCE_BELOW = (13, 12)      # the force's column there: u = f − Sᵀ p^A
ABOVE = (6, 6)              # a column from the body on, root first: m − wᵀ a, or a + S q̈


@dataclass(frozen=True)
class ArticulatedInverse:
    """articulated_inverse writing M⁻¹ whole (column-major nv × nv) into `output`, the same array
    looped_inverse.LoopedInverse would write (∂a/∂τ), so that the low-rank product reads it alike,
    and a = M⁻¹r into solve_a from the terms' r (Sᵀτ + Jᵀf − c − g);
    `comparison`: (its multiplications, those of the looped CRBA, factor and Zᵀ D⁻¹ Z), for the banner."""
    robot: object
    comparison: Tuple[int, int] = (0, 0)
    output: str = "da_dtau"
    simd_doubles: int = 4  # columns per vector instruction the cost model assumes (looped_solve.SIMD_DOUBLES)
    pays: ClassVar[bool] = True  # as a LoopedInverse that is taken
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    def _pieces(self):
        """(per-body pieces, per-column pieces), each (multiplications, additions), by trip count; the
        chain's body i on dof i − 1."""
        nb = self.robot.nb
        nv = nb - 1
        bodies, columns = body_tree.root_frame_pieces(self.robot), []
        for i in range(nb - 1, 0, -1):  # leaves first
            inner = i < nb - 1
            bodies += [APPLY, PROJECTION, (6, 1)]  # U, Sᵀ U + armature, w = D⁻¹ U
            bodies += [ACCUMULATE, SYMMETRIC_APPLY, (0, 6), OUTER] if inner else [(OUTER[0], 0)]
            bodies += [FORCE_BELOW] if inner else [(FORCE_BELOW[0] - PROJECTION[0], 0)]  # the force's column
            columns += [BELOW] * (nv - i)  # the columns after the body's own
        for i in range(2, nb):  # root first: the first body's columns need no wᵀ a, the last body's no a
            columns += [ABOVE] * (nv - i + 1)
            columns += [ABOVE] * (nv - i) if i < nb - 1 else []
            bodies += [ABOVE] + ([ABOVE] if i < nb - 1 else [])  # the force's column
        columns += [(ABOVE[0], 0)] * (nv - 1) if nb > 2 else []
        bodies += [(ABOVE[0], 0)] if nb > 2 else []
        return bodies, columns

    def operations(self):
        pieces = [piece for part in self._pieces() for piece in part]
        return {"mul": sum(m for m, _ in pieces), "add": sum(a for _, a in pieces),
                "div": self.robot.nb - 1, "neg": self.robot.nb - 1}

    def instructions(self):
        """Per body as the tree loops count theirs (looped_crba.LoopedCrba: the larger of the two counts,
        a step's overhead each); per column, SIMD across the columns, a load and a multiply-add per
        multiplication, simd_doubles columns at a time (as looped_inverse.LoopedInverse)."""
        bodies, columns = self._pieces()
        per_body = max(sum(m for m, _ in bodies), sum(a for _, a in bodies)) + STEP_OVERHEAD * 2 * self.robot.nb
        return per_body + 2 * sum(m for m, _ in columns) // self.simd_doubles

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        """The tree's table, then the loop (the low-rank product's RNEA loop reads the same table and a)."""
        return [body_tree.table(self.robot), f"alignas(64) Scalar solve_a[{self.robot.nv}];",
                f"articulated_inverse<Scalar, {self.robot.nb}, {self.robot.nv}>(tree, solve_X, solve_r, {self.output}, solve_a);"]
