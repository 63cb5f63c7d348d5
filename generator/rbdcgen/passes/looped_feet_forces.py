"""The feet's force-term derivatives ∂(Jᵀf)/∂q as a loop over the dof tree's ancestor pairs: the
looped form of feet_force_term_derivatives, and part of forward_dynamics_derivatives' looped solves
whose RNEA derivatives are a loop too (looped_solve.py). Not for a mimic-coupled robot (its term
is traced and projected, project.py).

Unrolled (algorithms/feet_force_derivatives.py), the term is one straight-line dot product per
(dof, ancestor) pair of each foot's path: O(n·depth) statements, 54 553 for a 100-body chain with a
foot at its tip, which took its ∂q̈ header past 20 s of g++. Each entry is ω_x · χ_y, so the traced
part writes the dofs' world axes ω and the force moments χ (O(n)), and add_feet_force_term_derivatives
(rbdc_gen/solve.hpp) forms the entries in the right-hand sides' ∂q columns. It folds nothing (the
trunk's translations, whose ω is zero, are multiplied too); what it saves is code."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.feet_force_derivatives import rows_with_feet
from ..algorithms.forward_dynamics import dof_ancestors, dof_parents
from . import body_tree
from .trace import Argument, with_loop

NAME = "feet_force_term_derivatives"
TERMS = "feet_force_term_derivative_moments"  # the traced part: the dofs' axes and force moments
DOT = (3, 2)


@dataclass(frozen=True)
class LoopedFeetForces:
    """add_feet_force_term_derivatives over `parents` (the dof tree), for the dofs `rows`, from the
    terms' feet_axes and feet_moments into `target`: row-major right-hand sides `stride` wide, or
    (`stride` 0) the column-major nv × nv output, cleared first, whose terms are `terms`."""
    parents: Tuple[int, ...]
    root_dofs: int
    rows: Tuple[int, ...]
    target: str
    stride: int = 0
    terms: Tuple[Argument, ...] = ()
    headers: ClassVar[Tuple[str, ...]] = ("rbdc_gen/solve.hpp",)

    def _pairs(self):
        return sum(len(dof_ancestors(self.parents, y)) for y in self.rows)

    def operations(self):
        """Per entry a dot product and an addition; an ancestor's entry is added twice, (y, x) and (x, y)."""
        entries = 3 * self.root_dofs + len(self.rows) + self._pairs()
        return {"mul": DOT[0] * entries, "add": (DOT[1] + 1) * entries + self._pairs()}

    def instructions(self):
        """The arithmetic fused, and STEP_OVERHEAD per entry (its loads and stores)."""
        ops = self.operations()
        entries = 3 * self.root_dofs + len(self.rows) + self._pairs()
        return max(ops["mul"], ops["add"]) + body_tree.STEP_OVERHEAD * entries

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        """The C++ statements; in a solve, after its declaration of the dof tree's table `dof_tree`."""
        from .looped_solve import dof_tree  # it imports this module
        n, rows = len(self.parents), self.rows
        strides = f"{self.stride}, 1" if self.stride else f"1, {n}"
        own = [] if self.stride else [dof_tree(self.parents),
                                      f"for (int k = 0; k < {n * n}; ++k) {self.target}[k] = Scalar(0);"]
        return own + [f"const int feet_rows[{max(1, len(rows))}] = {{{', '.join(map(str, rows)) or '0'}}};",
                      f"add_feet_force_term_derivatives<Scalar, {n}, {strides}, {_entries(self.parents)}, "
                      f"{self.root_dofs}, {len(rows)}>(dof_tree, feet_rows, solve_feet_axes, solve_feet_moments, "
                      f"{self.target});"]

    def emission(self, terms_name):
        return ("looped feet force terms: %s writes each dof's world axis and force moment, "
                "add_feet_force_term_derivatives forms the entries over the dof tree's %d ancestor pairs"
                % (terms_name, self._pairs()))


def has_looped_form(robot, name):
    return name == NAME and not robot.couplings


def looped_function(robot, scene, name):
    """feet_force_term_derivatives in its looped form: the traced axes and moments, then the loop."""
    def loop(terms, outputs):
        return LoopedFeetForces(parents=tuple(dof_parents(robot)), root_dofs=robot.root_dofs,
                                rows=rows_with_feet(robot, scene.feet_for(robot)), target=outputs[0].name,
                                terms=terms.outputs)
    return with_loop(robot, scene, name, TERMS, loop)


def _entries(parents):
    """The DofTree's entry count (looped_solve.dof_tree: one unused entry when none)."""
    return max(1, sum(len(dof_ancestors(parents, i)) for i in range(len(parents))))
