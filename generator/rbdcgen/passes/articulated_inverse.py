"""M⁻¹ of a fixed-base chain by the articulated-body recursion (rbdc_gen::articulated_inverse), for
forward_dynamics_derivatives' low-rank form (looped_solve.low_rank_applies; docs/performance.md, "M⁻¹ by
the articulated-body recursion"): the ABA run for every unit torque at once, O(n²) multiply-adds on a
chain, where the looped CRBA, the factor M = Lᵀ D L and Zᵀ D⁻¹ Z (looped_inverse.py) take O(n³), and
q̈ with it from the RNEA's forces in the same loop. The loops' counts are also chain_loop.py's (a
chain's RNEA and forward dynamics as one loop)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.crba import depth_first_order
from . import body_tree
from .body_tree import ACCUMULATE, APPLY, CROSS, PROJECTION, SPATIAL_CROSS, STEP_OVERHEAD

HEADER = "rbdc_gen/articulated_inverse.hpp"
DOT8 = (8, 7)               # x · y padded to 8
# Each body leaves first: U = I^C S − P S − U_c k with c = Sᵀ U_c, k = D_c⁻¹ c; D = Sᵀ(I^C S − P S) +
# armature − c k; a's column (f − Sᵀ p^A − c a_c) D⁻¹ and p^A + U_c a_c; P + U_c w_cᵀ; w = D⁻¹ U (the
# vectors 8 wide: their padding is computed too).
BODY_LEAVES_FIRST = (APPLY, (48, 40), DOT8, (1, 0), (0, 8), DOT8, (1, 2), (8, 8),
                     DOT8, (2, 2), (8, 8), (48, 48), (8, 0))
BODY_ROOT_FIRST = (DOT8, DOT8, (1, 2), (8, 8))  # a − wᵀ p − (wᵀ S_above) a_above; p + S_above a_above
BELOW = (13, 12)            # a column from the body's on, leaves first: Sᵀ p^A, D⁻¹(δ − ·), p^A + U m
ABOVE = (6, 6)              # a column from the body's on, root first: m − wᵀ a, or a + S q̈
FOOT = ((9, 9), CROSS, (0, 6))  # p0 + E0ᵀ offset, p × f, the wrench off its body's force


def body_force_pieces(robot, velocity, acceleration, n_feet):
    """articulated_detail::body_forces' pieces and each body's Σ F from it on and Sᵀ of it, as (the
    pieces along the chain, the pieces SIMD across the bodies): the root frames' products and a, v and
    ΣF carried from body to body; each body's axis, subspace and inertia, (v_λ × S) q̇ (with
    `velocity`), S q̈ (with `acceleration`), I a and v ×* I v across them; the feet's wrenches."""
    nv = robot.nb - 1
    along = [(0, 6)] + ([(6, 6)] if velocity else []) + [(0, 6), PROJECTION]
    across = [APPLY] + ([SPATIAL_CROSS, (6, 0), APPLY, SPATIAL_CROSS, (0, 6)] if velocity else [])
    across += [(6, 6) if velocity else (6, 0)] if acceleration else []
    frames = [body_tree.ROOT_TRANSFORM] * sum(robot.parent[i] != 0 for i in range(1, robot.nb))
    return (frames + along * nv + list(FOOT) * n_feet,
            [body_tree.AXIS, body_tree.REVOLUTE_SUBSPACE, body_tree.CONGRUENCE] * nv + across * nv)


def forward_dynamics_pieces(robot, n_feet, unit_columns):
    """(pieces along the chain, pieces SIMD across the bodies, per-column pieces) of
    articulated_detail::forward_dynamics: the forces at q̈ = 0, τ − Sᵀ ΣF, the recursion (with
    `unit_columns`, M⁻¹'s as well)."""
    bodies, columns = recursion_pieces(robot.nb, unit_columns)
    along, across = body_force_pieces(robot, True, False, n_feet)
    return along + bodies + [(0, 1)] * (robot.nb - 1), across, columns


def feet_table(feet):
    """The C++ table of the feet (rbdc_gen::ChainFeet): (table body, offset) each."""
    bodies = ", ".join(str(body) for body, _ in feet) or "0"
    offsets = ", ".join("{%s}" % (", ".join(repr(float(o[r])) for _, o in feet) or "0.0") for r in range(3))
    return f"RBDC_TABLE ChainFeet<{len(feet)}> feet{{{{{bodies}}}, {{{offsets}}}}};"


def chain_feet(robot, scene):
    """Each of the scene's feet as (its body in the table's order, its offset)."""
    position = {body: k for k, body in enumerate(depth_first_order(robot))}
    return tuple((position[foot.body], tuple(foot.offset)) for foot in scene.feet_for(robot))


def recursion_pieces(nb, unit_columns):
    """(per-body pieces, per-column pieces) of articulated_detail::recursion on a chain of nb bodies
    (body i on dof i − 1), each (multiplications, additions), by trip count; with `unit_columns`, M⁻¹'s."""
    nv = nb - 1
    bodies, columns = [], []
    for i in range(nb - 1, 0, -1):  # leaves first
        bodies += ([ACCUMULATE] if i < nb - 1 else []) + list(BODY_LEAVES_FIRST)
    for i in range(2, nb):  # root first: the first body's a is its own
        bodies += BODY_ROOT_FIRST
    # M⁻¹ (inverse_columns, counted for one column a run): dof d's row from column d on, each way
    columns = [piece for d in range(nv) for piece in [BELOW] * (nv - d) + [ABOVE] * 2 * (nv - d)] if unit_columns else []
    return bodies, columns


def loop_instructions(bodies, columns, nb, simd_doubles=4):
    """Per body as the tree loops count theirs (looped_crba.LoopedCrba: the larger of the two counts,
    a step's overhead each); per column, SIMD across the columns, a load and a multiply-add per
    multiplication, simd_doubles columns at a time (as looped_inverse.LoopedInverse)."""
    per_body = max(sum(m for m, _ in bodies), sum(a for _, a in bodies)) + STEP_OVERHEAD * 2 * nb
    return per_body + 2 * sum(m for m, _ in columns) // simd_doubles


@dataclass(frozen=True)
class ArticulatedInverse:
    """articulated_inverse writing M⁻¹ whole (column-major nv × nv) into `output`, the same array
    looped_inverse.LoopedInverse would write (∂a/∂τ), so that the low-rank product reads it alike,
    and q̈ into solve_a, from the terms' transforms X and gravity g and the inputs v, τ and f (`feet`:
    chain_feet); `comparison`: (its multiplications, those of the looped CRBA, factor and Zᵀ D⁻¹ Z), for
    the banner."""
    robot: object
    feet: Tuple = ()
    comparison: Tuple[int, int] = (0, 0)
    output: str = "da_dtau"
    simd_doubles: int = 4  # columns per vector instruction the cost model assumes (looped_solve.SIMD_DOUBLES)
    pays: ClassVar[bool] = True  # as a LoopedInverse that is taken
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    def operations(self):
        pieces = [piece for part in forward_dynamics_pieces(self.robot, len(self.feet), True) for piece in part]
        return {"mul": sum(m for m, _ in pieces), "add": sum(a for _, a in pieces),
                "div": self.robot.nb - 1, "neg": 3}  # −g

    def instructions(self):
        along, across, columns = forward_dynamics_pieces(self.robot, len(self.feet), True)
        return loop_instructions(along + across, columns, self.robot.nb, self.simd_doubles)

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        """The tree's table, then the loop (the low-rank product's RNEA loop reads the same table and a)."""
        nb, nv, nf = self.robot.nb, self.robot.nv, len(self.feet)
        return [body_tree.table(self.robot), feet_table(self.feet), f"alignas(64) Scalar solve_a[{nv}];",
                f"articulated_inverse<Scalar, {nb}, {nv}, {nf}>(tree, feet, solve_X, solve_g, v, tau, f, {self.output}, "
                f"solve_a);"]
