"""The looped form of the operational-space recursions osc_open_chain and osc_closed_chain
(docs/performance.md, "The operational-space columns as a loop").

Unrolled, paper 001's Table 1 carries each body's column of J̄_tᵀ to every ancestor by a force
transform: O(n·depth) straight-line code (a 200-body chain's: 48 MB per function, most of the
generator's four minutes). In the looped form the traced part runs the recursion for Λ_t and b_t
(O(n)) and writes each body's S_i and w_i in world coordinates (algorithms/osc.column_terms);
osc_columns_loop (rbdc_gen/osc.hpp) carries the columns there, a dot product and a multiply-add per
(body, ancestor) pair, SIMD across a body's descendants, and moves each to the trunk's coordinates."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from . import body_tree
from .body_tree import ancestor_steps
from .trace import Argument, with_loop

NAMES = ("osc_open_chain", "osc_closed_chain")
HEADER = "rbdc_gen/osc.hpp"
# Past this many (body, ancestor) steps the unrolled columns are not traced (a 45-body chain; Talos
# has 238): a 200-body chain's 19 900 are 48 MB of C++ per function.
UNROLL_LIMIT = 1000
PAIR = (12, 11)      # per (body, ancestor) pair: s = S_iᵀ c, c −= s w_i
TO_TRUNK = (24, 18)  # per column, world → trunk coordinates: (R_0ᵀ (n − p_0 × f), R_0ᵀ f)
# Instructions per pair step: the arithmetic fused (12), the column's six loads and six stores.
PAIR_INSTRUCTIONS = 24
SIMD_DOUBLES = 4     # columns per instruction the cost model assumes for a run (AVX2); the rest scalar
# Per body: its column's start and store and what its run costs beyond its steps (the wait on the
# previous body's stores of the same columns, the run's branches), set so that the cost model gives
# the ratios measured on humanoid32 (runs of at most 6; Zen 4, clang 14): osc_open_chain looped
# 2 085 ns against 1 750 unrolled, osc_closed_chain 2 100 against 1 720. (An earlier loop in the
# trunk's coordinates measured even on Talos: open chain 5 % faster looped, closed 8 % slower.)
BODY_INSTRUCTIONS = 186
COPIED = 42          # Λ_t and b_t from the traced part's locals


def _runs(robot):
    """The length of each body's run of descendant columns, in the table's depth-first order."""
    ends = body_tree.subtree_ends(body_tree.table_parents(robot))
    return [ends[i] - i - 1 for i in range(1, robot.nb)]


@dataclass(frozen=True)
class LoopedOsc:
    """osc_columns_loop over the robot's bodies, reading the terms' `columns` and copying Λ_t and b_t."""
    robot: object
    terms: Tuple[Argument, ...]
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    def operations(self):
        steps, columns = ancestor_steps(self.robot), self.robot.nb - 1
        return {"mul": PAIR[0] * steps + TO_TRUNK[0] * columns, "add": PAIR[1] * steps + TO_TRUNK[1] * columns,
                "neg": 6 * columns}

    def instructions(self):
        """A run's pairs SIMD_DOUBLES at a time, its remainder one by one, and BODY_INSTRUCTIONS per body."""
        pair_steps = sum(run // SIMD_DOUBLES + run % SIMD_DOUBLES for run in _runs(self.robot))
        return PAIR_INSTRUCTIONS * pair_steps + BODY_INSTRUCTIONS * (self.robot.nb - 1) + COPIED

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        robot = self.robot
        return [body_tree.table(robot),
                "for (int k = 0; k < 36; ++k) Lambda[k] = solve_Lambda[k];",
                "for (int k = 0; k < 6; ++k) b[k] = solve_b[k];",
                f"osc_columns_loop<Scalar, {robot.nb}, {robot.nv}, {robot.n_joints}>(tree, solve_columns, JbarT);"]

    def emission(self, terms_name):
        return ("looped operational-space columns: %s writes Λ_t, b_t and the %d bodies' S_i and w_i, "
                "osc_columns_loop carries J̄ᵀ's columns over a table of the tree (%d body-ancestor steps)"
                % (terms_name, self.robot.nb - 1, ancestor_steps(self.robot)))


def has_looped_form(robot, name):
    """On a tree of bodies alone (body_tree.applies: its table has no rotors)."""
    return name in NAMES and body_tree.applies(robot)


def unrolled_too_large(robot):
    return ancestor_steps(robot) > UNROLL_LIMIT


def looped_function(robot, scene, name):
    """`name` in its looped form: the traced Λ_t, b_t and column terms, with the loop as a LoopedOsc."""
    return with_loop(robot, scene, name, name + "_terms", lambda terms, _: LoopedOsc(robot=robot, terms=terms.outputs))
