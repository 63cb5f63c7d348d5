"""The looped form of forward_dynamics_derivatives (docs/performance.md, "Looped solves").

∂a is M⁻¹ applied to 2·nv + n_joints + 3·n_feet right-hand sides. Unrolled, every column's sparse
solve is straight-line code of its own: O(nv · columns) statements that stream through the
instruction cache on every call and take g++ minutes on a humanoid. In the looped form the traced
part writes the right-hand sides side by side (row-major) and the factor's tree entries into local
arrays, and one loop over the dofs (ltdl_solve_columns, rbdc_gen/solve.hpp) updates a whole row of
right-hand sides at a time: the columns are independent, so each update is one SIMD multiply-add
over all of them, and its code does not grow with the robot."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Tuple

from ..algorithms.forward_dynamics import dof_ancestors, dof_parents
from . import differentiate
from .trace import Argument, signature, trace_function

# The functions with a looped form, and the traced function that writes what they solve.
TERMS = {"forward_dynamics_derivatives": "forward_dynamics_derivative_terms"}
# Doubles per vector instruction the cost model assumes: AVX2, the widest every x86-64 machine we
# build for has (AVX-512 halves the loop's instructions again).
SIMD_DOUBLES = 4


@dataclass(frozen=True)
class LoopedSolve:
    """M⁻¹ B for the columns of B = [blocks], solved in place by ltdl_solve_columns; block k is
    output blocks[k][0], blocks[k][1] columns wide. `terms`: the local arrays the traced part
    writes (rhs, L, D_inv of differentiate.forward_dynamics_derivative_terms)."""
    parents: Tuple[int, ...]
    blocks: Tuple[Tuple[str, int], ...]
    terms: Tuple[Argument, ...]

    @property
    def nv(self):
        return len(self.parents)

    @property
    def columns(self):
        return sum(width for _, width in self.blocks)

    @property
    def factor_entries(self):
        return sum(len(dof_ancestors(self.parents, i)) for i in range(self.nv))

    def operations(self):
        """Multiplications and additions of the loop: per column, one multiply-add per factor entry
        on the way up and on the way down, one multiplication per pivot."""
        entries, columns = self.factor_entries, self.columns
        return {"mul": columns * (2 * entries + self.nv), "add": columns * 2 * entries}

    def instructions(self):
        """Vector instructions of the loop (a row update over the columns, SIMD_DOUBLES at a time)."""
        vectors = -(-self.columns // SIMD_DOUBLES)
        return vectors * (4 * self.factor_entries + self.nv)


def looped_function(robot, scene, name):
    """`name` in its looped form: the traced terms, with the solve as a LoopedSolve."""
    doc, inputs, outputs = signature(robot, scene, name)
    terms = trace_function(robot, scene, TERMS[name])
    blocks = tuple((arg.name, arg.cols) for arg in outputs if arg.cols)
    solve = LoopedSolve(parents=tuple(dof_parents(robot)), blocks=blocks, terms=terms.outputs)
    assert [a.name for a in outputs] == list(differentiate.FORWARD_DYNAMICS_COLUMNS)
    assert terms.inputs == inputs and terms.outputs[0].cols == solve.columns
    return replace(terms, name=name, doc=doc, outputs=outputs, computes=name, solve=solve)
