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
recursion; what it saves is code. A mimic-coupled robot's loop runs on its tree (views/coupled.py):
its velocity and acceleration expanded (G v, G a), each entry projected as it is written (Gᵀ X G)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.crba import depth_first_order
from ..views.coupled import tree_view, velocity_columns
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
COLUMN_LANE = (12, 10)    # the column's two entries alone (a chain's written by columns, columns_above)
COLUMN_LANE_AT_REST = (6, 5)
FEET_LANE = (3, 4)        # with the feet's force terms: ω_j·χ_i, taken from the row's entry and the column's
FEET_TRUNK_ROW = (9, 12)  # per body below a floating trunk: ω_k·χ_i for its three rotations, from two entries
FEET_TRUNK_BLOCK = (54, 54)  # the trunk's block: ω_k·χ_r for its rotations k and six dofs r
PRODUCT_BLOCK = 8         # the entries run in blocks of 8 descendants (kBlock)
# What one counted instruction of the loop costs (schedule.py's units) where it subtracts ∂τ from a
# looped solve's right-hand sides, not body_tree.LOOP_WEIGHT: by perf inside ∂q̈ (Zen 5, clang 14),
# 0.089 ns on humanoid32 and 0.102 ns on TALOS, against 0.084 for short straight-line code.
SUBTRACTING_WEIGHT = 1.1
SIMD_DOUBLES = 4          # lanes per instruction the cost model assumes for the blocks (AVX2)
# The loop's own code, as straight-line instructions: what it occupies in the front end beside the
# traced part of its function (schedule.cost). `nm -S` of the loop and the helpers it calls (clang 14,
# -O3 -march=native, Zen 5): 15.7 KB on Panda, 21.8 KB on chain100, 20-22 KB on humanoid32 and 26-29
# KB on TALOS, at 8.6 bytes a counted straight-line instruction (arm7's ∂τ: 20 573 bytes for 2 372).
CODE = 2300


def column_lanes(robot):
    """The lanes of a chain's columns above the diagonal (columns_above): for each body i ≥ 2, the
    blocks of PRODUCT_BLOCK bodies from body 0 that cover its ancestors 1 … i − 1."""
    return sum(-(-i // PRODUCT_BLOCK) * PRODUCT_BLOCK for i in range(2, robot.nb))


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
    the function's own v and the acceleration `acceleration_source` (`velocity`, `acceleration`:
    whether they enter), writing through `writer` (the declaration of its output `out`, one of the
    loop's writer types): the outputs themselves, or (`subtracting`) subtracted from a looped solve's
    right-hand sides. `robot` is the tree the loop runs on; `coupling`, for a coupled robot, G as per
    tree dof (independent dof, multiplier): the writer then projects (Projected) and the loop reads
    v and a expanded."""
    robot: object
    terms: Tuple[Argument, ...]
    writer: str
    velocity: bool
    acceleration: bool
    acceleration_source: str = "a"
    subtracting: bool = False
    coupling: Tuple[Tuple[int, float], ...] = ()
    low_rank: bool = False  # the writer takes the per-body vectors (InverseTimesVectors, looped_solve.low_rank_applies)
    feet: bool = False  # the feet's ∂(Jᵀf)/∂q taken from the ∂τ/∂q entries (the terms' feet axes and moments)
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    @property
    def columns_above(self):
        """Whether the loop writes the entries above the diagonal column by column (a chain, BodyTree's
        `chain`, into DenseDerivatives: rbdc_gen::ColumnsAbove), not along each body's row."""
        joints = [self.robot.joints[i] for i in depth_first_order(self.robot)]
        return (self.writer.startswith("DenseDerivatives") and not self.feet
                and body_tree.is_chain(body_tree.table_parents(self.robot)) and body_tree.depth_first_dofs(joints))

    def _counts(self, vector_width=1, padding=True):
        """(multiplications, additions) of rnea_derivatives_loop, by trip count; the entries' blocks
        along the subtrees as `vector_width` lanes per instruction. The loops SIMD across the bodies
        run over the padding and the root too; without `padding`, over the bodies they are for (the
        cost model's instructions: the padding rides in the bodies' vectors)."""
        robot, velocity = self.robot, self.velocity
        floating = robot.floating_base
        pieces = body_tree.root_frame_pieces(robot)
        pieces += [(0, 3)] + ([CROSS, (0, 3)] if floating and velocity else [])  # the root's a
        padded = -(-robot.nb // PRODUCT_BLOCK) * PRODUCT_BLOCK
        bodies = range(padded) if padding else range(1, robot.nb)
        for i in range(1, robot.nb):  # outward: v, u and a
            pieces += [SPATIAL_CROSS, (12, 12)] if velocity else []
            pieces += [(6, 6)] if self.acceleration else []
        for i in bodies:  # c
            pieces += [SPATIAL_CROSS] + ([SPATIAL_CROSS, (0, 6)] if velocity else [])
        for i in range(padded) if padding else range(0 if floating else 1, robot.nb):  # forces, momenta, rates
            pieces += [APPLY] + ([APPLY, SPATIAL_CROSS, (0, 6), INERTIA_RATE] if velocity else [])
        for i in range(1, robot.nb):  # inward sums
            if floating or robot.parent[i] != 0:
                pieces += [ACCUMULATE, (0, 6)] + ([MASSLESS_ACCUMULATE, (0, 6)] if velocity else [])
        for i in bodies:  # ρ, G, D
            pieces += [APPLY, SPATIAL_CROSS, APPLY, (0, 6)]
            if velocity:
                pieces += [APPLY, SPATIAL_CROSS, APPLY, (6, 18), APPLY, SPATIAL_CROSS, (0, 12)]
        for i in range(1, robot.nb):  # the trunk's rows and columns with each body
            if floating:
                pieces += [CROSS] + ([_times(CROSS, 2), (3, 6)] if velocity else [])
        if self.low_rank:  # InverseTimesVectors instead of the entries
            pieces.append(tuple(n // vector_width for n in low_rank_counts(robot)))  # SIMD along M⁻¹'s rows
            return sum(m for m, _ in pieces), sum(a for _, a in pieces)
        # the entries along each body's subtree, blocks of PRODUCT_BLOCK bodies, padding included
        lane = SUBTREE_LANE if velocity else SUBTREE_LANE_AT_REST
        lane = tuple(x + y for x, y in zip(lane, FEET_LANE)) if self.feet else lane
        if self.columns_above:  # the rows along the subtrees, the columns above the diagonal by columns
            column = COLUMN_LANE if velocity else COLUMN_LANE_AT_REST
            lane = (lane[0] - column[0], lane[1] - column[1])
            pieces.append(_times(column, column_lanes(robot) // vector_width))
        pieces.append(_times(lane, subtree_lanes(robot) // vector_width))
        if floating:  # the trunk's block
            pieces += [_times(CROSS, 3), _times(APPLY, 3)]
            pieces += [_times(FEET_TRUNK_ROW, robot.nb - 1), FEET_TRUNK_BLOCK] if self.feet else []
            if velocity:
                pieces += [_times(APPLY, 6), _times(SPATIAL_CROSS, 6), (0, 36),
                           _times(CROSS, 6), (9, 0), _times(APPLY, 3), (0, 18)]
        if self.subtracting:
            pieces.append((0, self._writes()))
        if self.coupling:  # the expanded inputs; a multiplication per entry projected, an addition summing it
            pieces += [(robot.nv * (self.velocity + self.acceleration), 0),
                       (self._writes(), 0 if self.subtracting else self._writes())]
        return sum(m for m, _ in pieces), sum(a for _, a in pieces)

    def _writes(self):
        """Entries the loop writes: per body j, its subtree's rows and (below the diagonal) columns;
        with a floating trunk, its rows and columns with each body and its own block."""
        robot = self.robot
        ends = body_tree.subtree_ends(body_tree.table_parents(robot))
        pairs = sum(2 * (ends[j] - j) - 1 for j in range(1, robot.nb))
        trunk = robot.floating_base
        q = pairs + (9 * (robot.nb - 1) + 18 if trunk else 0)
        v = pairs + (12 * (robot.nb - 1) + 36 if trunk else 0) if self.velocity else 0
        return q + v

    def operations(self):
        mul, add = self._counts()
        return {"mul": mul, "add": add, **({"neg": LOW_RANK_NEGATIONS * (self.robot.nb - 1)} if self.low_rank else {})}

    def instructions(self):
        """The arithmetic as max(multiplications, additions) (fused), the blocks SIMD_DOUBLES lanes at a
        time, and STEP_OVERHEAD per ancestor step and twice per body."""
        mul, add = self._counts(SIMD_DOUBLES, padding=False)
        return max(mul, add) + STEP_OVERHEAD * (ancestor_steps(self.robot) + 2 * self.robot.nb)

    def cost(self):
        return (SUBTRACTING_WEIGHT if self.subtracting else body_tree.LOOP_WEIGHT) * self.instructions()

    def loops(self, with_table=True):
        """The C++ statements; `with_table` False where another loop already declared the tree's table."""
        robot = self.robot
        flags = ", ".join("true" if x else "false" for x in (robot.floating_base, self.velocity, self.acceleration))
        v = "v" if self.velocity else "nullptr"
        a = self.acceleration_source if self.acceleration else "nullptr"
        statements = [body_tree.table(robot)] * with_table
        if self.coupling:
            statements += [f"RBDC_TABLE int tree_column[{robot.nv}] = {{{', '.join(str(k) for k, _ in self.coupling)}}};",
                           f"RBDC_TABLE double tree_weight[{robot.nv}] = {{{', '.join(repr(w) for _, w in self.coupling)}}};"]
            expanded = {}
            for name, used, source in (("v", self.velocity, v), ("a", self.acceleration, a)):
                expanded[name] = f"{name}_tree" if used else source
                statements += [f"Scalar {name}_tree[{robot.nv}];",
                               f"expand_coordinates<Scalar, {robot.nv}>(tree_column, tree_weight, {source}, {name}_tree);"] * used
            v, a = expanded["v"], expanded["a"]
        feet = ", FeetForceTerms<Scalar>{solve_feet_axes, solve_feet_moments}" if self.feet else ""
        return statements + [f"const {self.writer};",
                             f"rnea_derivatives_loop<Scalar, {robot.nb}, {robot.nv}, {flags}>(tree, solve_X, solve_g, {v}, {a}, out{feet});"]

    def emission(self, terms_name):
        return ("looped RNEA derivatives: %s writes the %d bodies' transforms and gravity, "
                "rnea_derivatives_loop runs the recursion over a table of the tree (%d body-ancestor steps)"
                % (terms_name, self.robot.nb - 1, ancestor_steps(self.robot)))


# InverseTimesVectors per body: T's update (15 multiply-adds a row) and column j's A·C parts (15 for ∂q,
# 12 for ∂v) from the tip; from the root, below the first body, its S·G parts (9 and 6, each added to
# the column) and, for every body, R's update (9). Negations: −c, −u, −S, −G, −D; −2u a multiplication.
LOW_RANK_NEGATIONS = 30


def low_rank_counts(robot):
    """(multiplications, additions) of InverseTimesVectors on `robot` (a fixed-base chain)."""
    bodies, nv = robot.nb - 1, robot.nv
    below_first = bodies - 1
    mul = (15 + 15 + 12 + 9) * nv * bodies + 6 * bodies + (9 + 6) * nv * below_first
    add = (15 + 14 + 11 + 9) * nv * bodies + (9 + 6) * nv * below_first
    return mul, add


def has_looped_form(robot, name):
    """On a tree of bodies alone, or a mimic-coupled one (the loop on its tree, projected)."""
    return name in TERMS and body_tree.applies(tree_view(robot))


def _writer(robot, target):
    """The declaration of the loop's writer `out` around `target` (a writer type and its initialiser),
    projected onto a coupled robot's coordinates; returns it and the coupling."""
    if not robot.couplings:
        return f"{target[0]} out{{{target[1]}}}", ()
    coupling = tuple(velocity_columns(robot))
    projected = f"Projected<Scalar, {tree_view(robot).nv}, {target[0]}>"
    return f"{projected} out{{tree_column, tree_weight, {{{target[1]}}}}}", coupling


def unrolled_too_large(robot):
    return ancestor_steps(robot) > UNROLL_LIMIT


def looped_function(robot, scene, name):
    """`name` in its looped form: the traced transforms, with the loop as a LoopedRneaDerivatives."""
    def loop(terms, outputs):
        inputs = {arg.name for arg in terms.inputs}
        dv = outputs[1].name if len(outputs) > 1 else "nullptr"
        kind = "SummedDerivatives" if robot.couplings else "DenseDerivatives"
        writer, coupling = _writer(robot, (f"{kind}<Scalar, {robot.nv}>", f"{outputs[0].name}, {dv}"))
        return LoopedRneaDerivatives(robot=tree_view(robot), terms=terms.outputs, writer=writer,
                                     velocity="v" in inputs, acceleration="a" in inputs, coupling=coupling)
    return with_loop(robot, scene, name, TERMS[name], loop)


def subtracted_from(robot, terms, rhs, columns, place="", feet=False):
    """The loop that subtracts ∂τ/∂q and ∂τ/∂v at the terms' acceleration `a` from the right-hand
    sides `rhs` (row-major, `columns` wide, ∂/∂q and ∂/∂v in its first 2 nv columns, or with `place`
    where that table puts them): a looped solve's (looped_solve.py); with `feet`, ∂τ/∂q less the
    feet's ∂(Jᵀf)/∂q."""
    placed = (f"SubtractedFromColumns<Scalar, {robot.nv}, {columns}, true>", f"{rhs}, {place}") if place else \
        (f"SubtractedFromColumns<Scalar, {robot.nv}, {columns}>", rhs)
    writer, coupling = _writer(robot, placed)
    return LoopedRneaDerivatives(robot=tree_view(robot), terms=terms, writer=writer, velocity=True,
                                 acceleration=True, acceleration_source="solve_a", subtracting=True,
                                 coupling=coupling, feet=feet)


def inverse_times_vectors(robot, terms, feet):
    """The loop whose writer forms ∂a/∂q and ∂a/∂v from M⁻¹ (already in da_dtau) and the per-body
    vectors (InverseTimesVectors: a fixed-base chain's low-rank product, looped_solve.LoopedSolve with
    low_rank); `feet`: whether the terms hold the feet's axes and moments."""
    axes = "solve_feet_axes, solve_feet_moments" if feet else "nullptr, nullptr"
    writer = f"InverseTimesVectors<Scalar, {robot.nv}> out{{da_dtau, {axes}, da_dq, da_dv}}"
    return LoopedRneaDerivatives(robot=robot, terms=terms, writer=writer, velocity=True, acceleration=True,
                                 acceleration_source="solve_a", low_rank=True)
