"""The feet's force-term derivatives ∂(Jᵀf)/∂q as a loop over the dof tree's ancestor pairs: the
looped form of feet_force_term_derivatives (forward_dynamics_derivatives' looped solves whose RNEA
derivatives are a loop take the same terms on that loop's entries: looped_rnea_derivatives.py). A
mimic-coupled robot's loop runs on its tree, each entry projected as it is written (Gᵀ X G, as the
looped RNEA derivatives').

Unrolled (algorithms/feet_force_derivatives.py), the term is one straight-line dot product per
(dof, ancestor) pair of each foot's path: O(n·depth) statements, 54 553 for a 100-body chain with a
foot at its tip, which took its ∂q̈ header past 20 s of g++. Each entry is ω_x · χ_y, so the traced
part writes the dofs' world axes ω and the force moments χ (O(n)), and add_feet_force_term_derivatives
(rbdc_gen/solve.hpp) forms the entries. It folds nothing (the trunk's translations, whose ω is zero,
are multiplied too); what it saves is code."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.feet_force_derivatives import rows_with_feet
from ..algorithms.forward_dynamics import dof_ancestors, dof_parents
from ..views.coupled import tree_view, velocity_columns
from . import body_tree
from .looped_solve import dof_tree
from .trace import Argument, with_loop

NAME = "feet_force_term_derivatives"
TERMS = "feet_force_term_derivative_moments"  # the traced part: the dofs' axes and force moments
DOT = (3, 2)
# What one counted instruction of the loop weighs in passes/schedule.py's units, as measured (clang 14,
# AMD EPYC Zen 4, one core): feet_force_term_derivatives unrolled against looped, in one driver:
# a floating 100-body chain 8.4 against 11.2 µs (costs 65 032 and 44 834 instructions), TALOS as
# shipped 1.27 against 2.2 µs (19 026 and 9 721 instructions, its entries projected). The unrolled
# term folds the zero axes and writes each entry once; the loop reads and writes each entry twice.
LOOP_WEIGHT = 3.5
# Past this many (dof, ancestor) pairs on the paths of the robot's feet the unrolled term is not
# traced: g++ 12 -O3 took 12.4 s on a 100-body chain's (4 950 pairs, 1.5 MB) and 38 s on a floating
# 200-body chain's (20 100 pairs, 6.1 MB), past issue 20's 20 s a header.
UNROLL_LIMIT = 8000


@dataclass(frozen=True)
class LoopedFeetForces:
    """add_feet_force_term_derivatives over `parents` (the tree's dof tree), for the dofs `rows`, from
    the terms' feet_axes and feet_moments into `target`, the column-major `columns` × `columns`
    output, cleared first, whose terms are `terms`. `coupling`, for a coupled robot, G as per tree
    dof (independent dof, multiplier): each entry is then projected. (In a looped ∂q̈ the RNEA loop
    takes the same terms from its entries: looped_rnea_derivatives.py.)"""
    parents: Tuple[int, ...]
    root_dofs: int
    rows: Tuple[int, ...]
    target: str
    columns: int
    terms: Tuple[Argument, ...] = ()
    coupling: Tuple[Tuple[int, float], ...] = ()
    headers: ClassVar[Tuple[str, ...]] = ("rbdc_gen/solve.hpp",)

    def _pairs(self):
        return sum(len(dof_ancestors(self.parents, y)) for y in self.rows)

    def _entries(self):
        """The entries computed: the trunk's block, each row's diagonal and its ancestor pairs."""
        return 3 * self.root_dofs + len(self.rows) + self._pairs()

    def operations(self):
        """Per entry a dot product and an addition; an ancestor's entry is added twice, (y, x) and (x, y);
        projected, a multiplication per addition."""
        entries = self._entries()
        writes = entries + self._pairs()
        return {"mul": DOT[0] * entries + (writes if self.coupling else 0), "add": DOT[1] * entries + writes}

    def instructions(self):
        """The arithmetic fused, and STEP_OVERHEAD per entry (its loads and stores)."""
        ops = self.operations()
        return max(ops["mul"], ops["add"]) + body_tree.STEP_OVERHEAD * self._entries()

    def cost(self):
        return LOOP_WEIGHT * self.instructions()

    def loops(self):
        """The C++ statements."""
        n, rows, columns = len(self.parents), self.rows, self.columns
        own = [dof_tree(self.parents, "feet_dof_tree"),
               f"for (int k = 0; k < {columns * columns}; ++k) {self.target}[k] = Scalar(0);",
               f"RBDC_TABLE int feet_rows[{max(1, len(rows))}] = {{{', '.join(map(str, rows)) or '0'}}};"]
        projection = ""
        if self.coupling:
            own += [f"RBDC_TABLE int feet_column[{n}] = {{{', '.join(str(k) for k, _ in self.coupling)}}};",
                    f"RBDC_TABLE double feet_weight[{n}] = {{{', '.join(repr(w) for _, w in self.coupling)}}};"]
            projection = ", feet_column, feet_weight"
        flags = ", true" if self.coupling else ""
        return own + [f"add_feet_force_term_derivatives<Scalar, {columns}, {self.root_dofs}, {len(rows)}{flags}>("
                      f"feet_dof_tree, feet_rows, solve_feet_axes, solve_feet_moments, {self.target}{projection});"]

    def emission(self, terms_name):
        return ("looped feet force terms: %s writes each dof's world axis and force moment, "
                "add_feet_force_term_derivatives forms the entries over the dof tree's %d ancestor pairs"
                % (terms_name, self._pairs()))


def has_looped_form(robot, name):
    return name == NAME


def path_pairs(robot):
    """The (dof, ancestor) pairs on the paths of all the robot's feet: the unrolled term's entries."""
    tree = tree_view(robot)
    parents = dof_parents(tree)
    return sum(len(dof_ancestors(parents, y)) for y in rows_with_feet(tree, tree.feet))


def unrolled_too_large(robot):
    return path_pairs(robot) > UNROLL_LIMIT


def on_tree(robot, scene, target, **keys):
    """The loop over `robot`'s tree (a coupled robot's projected) for the scene's feet, into `target`."""
    tree = tree_view(robot)
    return LoopedFeetForces(parents=tuple(dof_parents(tree)), root_dofs=robot.root_dofs,
                            rows=rows_with_feet(tree, scene.feet_for(robot)), target=target, columns=robot.nv,
                            coupling=tuple(velocity_columns(robot)) if robot.couplings else (), **keys)


def looped_function(robot, scene, name):
    """feet_force_term_derivatives in its looped form: the traced axes and moments, then the loop."""
    return with_loop(robot, scene, name, TERMS,
                     lambda terms, outputs: on_tree(robot, scene, outputs[0].name, terms=terms.outputs))
