"""∂a/∂τ = M⁻¹Sᵀ in forward_dynamics_derivatives' looped form as rows of M⁻¹ = Zᵀ D⁻¹ Z, Z = L⁻ᵀ
(rbdc_gen::ltdl_inverse), where that takes fewer multiply-adds than solving Sᵀ's columns with the
others (docs/performance.md, "∂a/∂τ as Zᵀ D⁻¹ Z"): on a deep chain, where every column's solve is
two passes over all nv² / 2 factor entries, while Z's column c is zero below row c and M⁻¹ is
symmetric. The right-hand sides then leave Sᵀ out (differentiate.forward_dynamics_derivative_terms)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Tuple

from ..algorithms.forward_dynamics import dof_ancestors, dof_parents

# ltdl_factor and ltdl_inverse (it includes the looped solve's rbdc_gen/solve.hpp).
FACTOR_HEADER = "rbdc_gen/factor.hpp"
# rbdc_gen::LTDL_INVERSE_COLUMNS: the columns each of ltdl_inverse's blocks takes at once.
BLOCK_COLUMNS = 16
# rbdc_gen::LTDL_PATH: the most rows of M⁻¹ one sweep sums (rows along a path).
PATH = 4
# ltdl_inverse is taken when its multiply-adds are at most this share of the solve's it replaces: its
# blocks carry two vector runs where the solve's carry up to twelve, so each of its multiply-adds costs
# more (chain100's M⁻¹, AMD EPYC Zen 4, clang 14: 543 200 in 28.2 µs, the solve of the identity's
# 1 029 600 in 38.8 µs; break-even at 0.73).
PAYS_BELOW = 0.7


@dataclass(frozen=True)
class LoopedInverse:
    """ltdl_inverse writing M⁻¹'s rows first … nv − 1 into `output` (column-major nv × (nv − first):
    M⁻¹Sᵀ when Sᵀ selects those dofs)."""
    parents: Tuple[int, ...]
    first: int
    comparison: Tuple[int, int] = (0, 0)  # (its multiply-adds, the solve's for Sᵀ's columns), for the banner
    simd_doubles: int = 4  # columns per vector instruction the cost model assumes (looped_solve.SIMD_DOUBLES)
    output: str = "da_dtau"
    headers = (FACTOR_HEADER,)

    def _blocks(self):
        """Per block of BLOCK_COLUMNS columns: the rows before its last dof's (the rows its passes run
        over), the padding columns in the first block."""
        n = len(self.parents)
        padding = -n % BLOCK_COLUMNS
        return [c1 - padding for c1 in range(BLOCK_COLUMNS, n + padding + 1, BLOCK_COLUMNS)]

    def _tiles(self, rows):
        """M⁻¹'s rows before `rows` as ltdl_inverse sums them, last first: (top row, size), each tile
        up to PATH rows along a path (rbdc_gen::path_size)."""
        a = rows - 1
        while a >= 0:
            size = 1
            while size < PATH and a - size >= 0 and self.parents[a - size + 1] == a - size:
                size += 1
            yield a, size
            a -= size

    def _counts(self):
        """(multiply-adds of Z's L⁻ᵀ pass, multiply-adds of the products, coefficients, products that
        start a sum) as the loops run them: per block, each row before its end takes its descendants
        before the end (one multiply-add per column); a tile of rows one coefficient Z(k, r) D⁻¹(k)
        per row and one product per row and column for its top row and each of the top's ancestors k."""
        ancestors = [len(dof_ancestors(self.parents, i)) for i in range(len(self.parents))]
        up = products = starts = 0
        for rows in self._blocks():
            up += sum(ancestors[:rows])  # (i, ancestor) pairs both before the block's end
            for top, size in self._tiles(rows):
                products += size * (ancestors[top] + 1)
                starts += size
        return up * BLOCK_COLUMNS, products * BLOCK_COLUMNS, products, starts * BLOCK_COLUMNS

    @property
    def pays(self):
        """Its multiply-adds at most PAYS_BELOW of the solve's for Sᵀ's columns."""
        own, saved = self.comparison
        return own <= PAYS_BELOW * saved

    def multiply_adds(self):
        up, products, _, _ = self._counts()
        return up + products

    def operations(self):
        """A sum's first product is a multiplication only."""
        up, products, coefficients, starts = self._counts()
        return {"mul": up + products + coefficients, "add": up + products - starts}

    def instructions(self):
        """A load and a multiply-add per simd_doubles columns, as the looped solve's row updates."""
        return 2 * self.multiply_adds() // self.simd_doubles

    def cost(self):
        return self.instructions()

    def loops(self, L="solve_L", D_inv="solve_D_inv"):
        return [f"ltdl_inverse<Scalar, {len(self.parents)}, {self.first}>(dof_tree, {L}, {D_inv}, {self.output});"]


def _solve_multiply_adds(parents, columns):
    return columns * 2 * sum(len(dof_ancestors(parents, i)) for i in range(len(parents)))


def compared(robot, feet_rows, padded) -> Optional[LoopedInverse]:
    """`robot`'s ∂a/∂τ as M⁻¹'s rows with its `comparison`, where it is possible (else None): Sᵀ must
    select the last dofs in order, one per joint (no couplings). `padded`: the right-hand sides' row
    length for a count of columns."""
    nv, nj = robot.nv, robot.n_joints
    first = nv - nj
    if robot.couplings or nj == 0 or [robot.joints[i].v_index for i in range(1, robot.nb)] != list(range(first, nv)):
        return None
    parents = tuple(dof_parents(robot))
    own = LoopedInverse(parents=parents, first=first).multiply_adds()
    saved = _solve_multiply_adds(parents, padded(2 * nv + nj + feet_rows) - padded(2 * nv + feet_rows))
    return LoopedInverse(parents=parents, first=first, comparison=(own, saved))


def tau_by_inverse(robot, feet_rows, padded) -> Optional[LoopedInverse]:
    """compared's LoopedInverse where it pays."""
    inverse = compared(robot, feet_rows, padded)
    return inverse if inverse is not None and inverse.pays else None
