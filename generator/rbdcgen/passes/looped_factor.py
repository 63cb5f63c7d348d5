"""The looped form of mass_matrix_factor (docs/performance.md, "The factor as a loop").

The sparse LᵀDL factorisation of M costs Σ_k Σ_{i ⊂ ancestors(k)} (depth(i) + 2) multiply-adds:
a few hundred on a legged robot, where its unrolled code folds and schedules well, but O(n³) on a
chain (a 100-body chain: 9.6 MB of straight-line code, and most of the generator's time and memory).
In the looped form the traced part writes only M's entries at each dof's ancestors and its diagonal
(the CRBA, O(n²) on a chain) into local arrays and ltdl_factor (rbdc_gen/factor.hpp) factorises them
in place: one multiply-add per entry of the ancestor row it updates, contiguous in the packed
layout, so the inner loop is a SIMD axpy. Its code does not grow with the robot. In the looped-CRBA
form (where the unrolled CRBA is past looped_crba.UNROLL_LIMIT, or a scene asks) the packed entries
come from the looped CRBA instead, and the traced part is only the bodies' transforms."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Tuple

from ..algorithms.forward_dynamics import dof_ancestors, dof_depths, dof_parents
from . import looped_crba
from .looped_inverse import FACTOR_HEADER
from .looped_solve import HEADER, SIMD_DOUBLES
from .trace import Argument, with_loop

TERMS = "mass_matrix_factor_terms"
# Above this many multiply-adds the factor is not traced unrolled at all, whatever `auto` would have
# found: the trace alone takes minutes and gigabytes (a 200-body chain: 1.3 million), and a loop's
# instruction count is then far below it. 20 000 is a 40-dof chain; humanoid32's factor has 766.
UNROLL_LIMIT = 20000
# Instructions per (k, ancestor) pair besides the row update: the ratio, the pivot's update, the
# walk to the next ancestor and the loop's own bookkeeping.
PAIR_OVERHEAD = 8
# What one counted instruction of the factor's loop costs in passes/schedule.py's units (short
# straight-line code), measured on an AMD EPYC (Zen 5), clang 14: 0.28-0.30 ns on humanoid32 and
# Talos (mass_matrix_factor looped 1.63 and 2.90 µs, straight-line 1.23 and 2.45 µs) against 0.084.
FACTOR_WEIGHT = 3.5


def factor_multiply_adds(parents):
    """The multiply-adds of the factorisation over the dof tree `parents`: for dof k and each ancestor
    i, the ratio, the update of i's pivot and of i's row (depth(i) entries)."""
    depth = dof_depths(parents)
    return sum(2 + depth[i] for k in range(len(parents)) for i in dof_ancestors(parents, k))


@dataclass(frozen=True)
class LoopedFactor:
    """M = Lᵀ D L by ltdl_factor over the packed entries the terms (L, D) hold, or `crba` writes from
    the terms' transforms, then unpacked into the outputs L (nv × nv), D and D_inv."""
    parents: Tuple[int, ...]
    terms: Tuple[Argument, ...]
    crba: Optional[looped_crba.LoopedCrba] = None
    unpack: bool = True  # False: the factor stays packed in solve_L, its inverse pivots in solve_D_inv

    @property
    def headers(self):
        return (HEADER, FACTOR_HEADER) + (() if self.crba is None else self.crba.headers)

    @property
    def nv(self):
        return len(self.parents)

    def _pairs(self):
        return [(k, i) for k in range(self.nv) for i in dof_ancestors(self.parents, k)]

    def operations(self):
        """The loop's arithmetic, by trip count: per dof one division (its inverse pivot); per
        (k, ancestor i) the ratio (a multiplication), the pivot update (a multiply-add) and the
        update of i's row (a multiply-add per entry)."""
        depth = dof_depths(self.parents)
        row = sum(depth[i] for _, i in self._pairs())
        pairs = len(self._pairs())
        counts = {"div": self.nv, "mul": 2 * pairs + row, "add": pairs + row}
        for kind, n in (() if self.crba is None else self.crba.operations().items()):
            counts[kind] = counts.get(kind, 0) + n
        return counts

    def instructions(self):
        """Vector instructions: a row update a load, a multiply-add and a store per SIMD_DOUBLES
        entries, plus PAIR_OVERHEAD per pair and one division per dof."""
        depth = dof_depths(self.parents)
        rows = sum(-(-depth[i] // SIMD_DOUBLES) for _, i in self._pairs())
        crba = 0 if self.crba is None else self.crba.instructions()
        return 3 * rows + PAIR_OVERHEAD * len(self._pairs()) + self.nv + crba

    def cost(self):
        """In passes/schedule.py's units: the factor's row updates weigh FACTOR_WEIGHT each."""
        own = self.instructions() - (0 if self.crba is None else self.crba.instructions())
        return FACTOR_WEIGHT * own + (0 if self.crba is None else self.crba.cost())

    def loops(self, with_table=True):
        crba = [] if self.crba is None else [
            "alignas(64) Scalar solve_L[%d];" % max(1, len(self._pairs())),
            "Scalar solve_D[%d];" % self.nv, *self.crba.loops(with_table)]
        pivots = "D_inv" if self.unpack else "solve_D_inv"
        body = crba + ([] if self.unpack else [f"Scalar solve_D_inv[{self.nv}];"]) + [
            "RBDC_TABLE int dof_parent[%d] = {%s};" % (self.nv, ", ".join(map(str, self.parents))),
            f"ltdl_factor<Scalar, {self.nv}>(dof_parent, solve_L, solve_D, {pivots});"]
        if self.unpack:
            body.append(f"unpack_factor<Scalar, {self.nv}>(dof_parent, solve_L, solve_D, L, D);")
        return body

    def emission(self, terms_name):
        source = ("%s writes M's %d entries at the dofs' ancestors and its diagonal" % (terms_name, self.terms[0].size)
                  if self.crba is None else self.crba.emission(terms_name) + ", into M's entries at the dofs' ancestors")
        return ("looped factor: %s, ltdl_factor factorises them in place (%d multiply-adds, a SIMD row update "
                "per ancestor pair)" % (source, factor_multiply_adds(self.parents)))


def has_looped_form(robot, name):
    """Only mass_matrix_factor, and not on a coupled robot (its factor is of the projected M)."""
    return name == "mass_matrix_factor" and not robot.couplings


def unrolled_too_large(robot):
    """Whether the unrolled factor is past UNROLL_LIMIT (passes/schedule.py then does not trace
    forms that unroll it)."""
    return factor_multiply_adds(dof_parents(robot)) > UNROLL_LIMIT


def looped_function(robot, scene, name, crba=False):
    """mass_matrix_factor in its looped form: the traced terms, with the loop as a LoopedFactor; with
    `crba`, M's entries from the looped CRBA (passes/looped_crba.py)."""
    def loop(terms, _):
        return LoopedFactor(parents=tuple(dof_parents(robot)), terms=terms.outputs,
                            crba=looped_crba.LoopedCrba(robot=robot, terms=terms.outputs, packed=True) if crba else None)
    return with_loop(robot, scene, name, looped_crba.TERMS if crba else TERMS, loop)
