"""The looped forms of forward_dynamics_derivatives and contact_dynamics_derivatives
(docs/performance.md, "Looped solves").

∂a is M⁻¹ applied to 2·nv + n_joints + 3·n_feet right-hand sides (for contact dynamics, with the
Delassus system's solve between two such solves, docs/generator.md). Unrolled, every column's sparse
solve is straight-line code of its own: O(nv · columns) statements that stream through the
instruction cache on every call and take g++ minutes on a humanoid. In the looped form the traced
part writes the right-hand sides side by side (row-major) and the factors into local arrays, and
loops (rbdc_gen/solve.hpp) update a whole row of right-hand sides at a time: the columns are
independent, so each update is one SIMD multiply-add over all of them, and its code does not grow
with the robot."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Optional, Tuple

from ..algorithms.contact_dynamics import PROXIMAL_STEPS
from ..algorithms.forward_dynamics import dof_ancestors, dof_parents, packed_starts
from ..graph import expr as ex
from . import (articulated_inverse, body_tree, column_support, differentiate, lane_contact_derivatives, lane_derivatives, looped_crba,
               looped_inverse, looped_rnea_derivatives)
from .column_support import ColumnSupport
from .looped_inverse import LoopedInverse
from .looped_rnea_derivatives import LoopedRneaDerivatives
from .trace import Argument, with_loop

# The functions with a looped form, and the traced function that writes what they solve.
TERMS = {"forward_dynamics_derivatives": "forward_dynamics_derivative_terms",
         "contact_dynamics_derivatives": "contact_dynamics_derivative_terms"}
# The terms when the RNEA's derivatives are a loop too (looped_rnea_derivatives.py), and when M's
# factor is as well (the looped CRBA and factor: looped_crba.py, looped_factor.py).
LOOP_TERMS = {"forward_dynamics_derivatives": "forward_dynamics_derivative_loop_terms"}
TREE_TERMS = {"forward_dynamics_derivatives": "forward_dynamics_derivative_tree_terms"}
LOW_RANK_TERMS = {"forward_dynamics_derivatives": "forward_dynamics_derivative_chain_terms"}
# Doubles per vector instruction the cost model assumes: AVX2, the widest every x86-64 machine we
# build for has (AVX-512 halves the loop's instructions again).
SIMD_DOUBLES = 4
HEADER = "rbdc_gen/solve.hpp"  # the loops
LOW_RANK_HEADER = "rbdc_gen/low_rank.hpp"  # InverseTimesVectors, inverse_times_columns


@dataclass(frozen=True)
class LoopedSolve:
    """M⁻¹ B for the columns of B = [blocks], solved in place by ltdl_solve_columns; block k is
    output blocks[k][0], blocks[k][1] columns wide, B's rows zero-padded to `columns`
    (differentiate.padded). `terms`: the local arrays the traced part writes (rhs, L, D_inv of
    differentiate.forward_dynamics_derivative_terms). `rnea`: the looped RNEA derivatives that
    complete the right-hand sides first, if any (with the feet's force-term derivatives on its
    entries); `factor`: the looped CRBA and factor (a
    looped_factor.LoopedFactor, packed) that write solve_L and solve_D_inv first, if the terms do not;
    `inverse`: ∂a/∂τ as M⁻¹'s rows (looped_inverse.py) where that is possible, taken where it pays (B
    then leaves Sᵀ out), its counts in the banner either way, or with `low_rank` M⁻¹ whole by the
    articulated-body recursion (articulated_inverse.py), the factor then not formed; `support`: B's columns sorted so that
    each block's L⁻ᵀ runs over its columns' non-zero rows only (column_support.py), B then in its
    `order`."""
    parents: Tuple[int, ...]
    blocks: Tuple[Tuple[str, int], ...]
    terms: Tuple[Argument, ...]
    rnea: Optional[LoopedRneaDerivatives] = None
    factor: object = None
    inverse: Optional[LoopedInverse | articulated_inverse.ArticulatedInverse] = None
    support: Optional[ColumnSupport] = None
    # per terms output whose entries a lane function keeps elsewhere than row-major (lane_places): where
    # each row-major entry is (None: zero, not stored)
    places: Tuple[Tuple[str, Tuple[Optional[int], ...]], ...] = ()
    column_order: Tuple[int, ...] = ()  # the logical column at each place of rhs (R1 and R2; empty: in order)
    # ∂a/∂q and ∂a/∂v formed from M⁻¹ by `rnea`'s writer (a fixed-base chain: low_rank_applies), and the
    # feet's columns as M⁻¹ times them: no solve
    low_rank: bool = False

    def placed(self, values):
        """The terms' values {name: row-major entries} where `places` keeps them."""
        placed = dict(values)
        for name, place in self.places:
            entries = [None] * len(values[name])
            for logical, p in enumerate(place):
                if p is not None:
                    entries[p] = values[name][logical]
            placed[name] = tuple(entries)
        return placed

    def _place(self, name, logical):
        """Where `places` keeps entry `logical` of terms output `name` (row-major if not listed)."""
        place = dict(self.places).get(name)
        return logical if place is None else place[logical]

    @property
    def taken_inverse(self):
        """`inverse` where it is taken, else None."""
        return self.inverse if self.inverse is not None and self.inverse.pays else None

    def _parts(self):
        return [part for part in (self.factor, self.rnea, self.taken_inverse) if part is not None]

    @property
    def headers(self):
        low_rank = (LOW_RANK_HEADER,) if self.low_rank else ()
        return tuple(dict.fromkeys((HEADER,) + tuple(h for part in self._parts() for h in part.headers) + low_rank))

    @property
    def nv(self):
        return len(self.parents)

    @property
    def width(self):
        """The right-hand sides the outputs take."""
        return sum(width for _, width in self.blocks)

    @property
    def columns(self):
        """The columns the loops sweep: the width, zero-padded."""
        return differentiate.padded(self.width)

    @property
    def factor_entries(self):
        return sum(len(dof_ancestors(self.parents, i)) for i in range(self.nv))

    def multiply_adds(self):
        """Per column: one multiply-add per factor entry on the way up and on the way down."""
        return 2 * self.factor_entries

    @property
    def solved_columns(self):
        """The columns the solve runs over: all, or none with `low_rank` (its feet's columns are M⁻¹'s
        product, feet_columns)."""
        return 0 if self.low_rank else self.columns

    @property
    def feet_columns(self):
        """With `low_rank`: the right-hand sides' columns after ∂/∂q and ∂/∂v (the feet's Jᵀ), which
        inverse_times_columns multiplies by M⁻¹."""
        return sum(width for _, width in self.blocks[2:]) if self.low_rank else 0

    def unread(self, name):
        """The entries of terms output `name` that no loop reads, so that the terms neither store nor
        clear them: with `low_rank`, every right-hand side but the feet's columns."""
        if not self.low_rank or name != self.terms[0].name:
            return ()
        first, columns = 2 * self.nv, self.columns
        return tuple(i for i in range(self.nv * columns) if not first <= i % columns < first + self.feet_columns)

    def _skipped(self, per_block):
        """Per block of `support`, per_block(columns, factor entries its L⁻ᵀ skips), summed."""
        blocks = self.support.widths_and_entries() if self.support else ()
        return sum(per_block(width, self.factor_entries - entries) for width, entries in blocks)

    def operations(self):
        """Multiplications and additions of the loops: multiply_adds() per column (less the entries
        L⁻ᵀ skips off each block's rows) and one multiplication per pivot."""
        updates = self.solved_columns * self.multiply_adds() - self._skipped(lambda width, skipped: width * skipped)
        updates += self.nv * self.nv * self.feet_columns  # inverse_times_columns
        ops = {"mul": updates + self.solved_columns * self.nv, "add": updates}
        for part in self._parts():
            for kind, n in part.operations().items():
                ops[kind] = ops.get(kind, 0) + n
        return ops

    def instructions(self):
        """Vector instructions of the loops (a row update over the columns, SIMD_DOUBLES at a time):
        a load and a multiply-add per multiply-add, one per pivot; the low-rank form's M⁻¹Jᵀ a load
        and a multiply-add per foot column for each column of M⁻¹ and run of rows."""
        return (-(-self.solved_columns // SIMD_DOUBLES) * (2 * self.multiply_adds() + self.nv)
                - self._skipped(lambda width, skipped: -(-width // SIMD_DOUBLES) * 2 * skipped)
                + (-(-self.nv // SIMD_DOUBLES) * self.nv * (1 + self.feet_columns) if self.feet_columns else 0)
                + sum(part.instructions() for part in self._parts()))

    def cost(self):
        """In passes/schedule.py's units: the row updates' instructions themselves, the other loops'
        as each weighs them."""
        return self.instructions() + sum(part.cost() - part.instructions() for part in self._parts())

    def _tree_solve(self, target, passes=None):
        """M⁻¹ on `target`, or one half of it (`passes`: rbdc_gen::Passes' up or down)."""
        which = "" if passes is None else f", Passes::{passes}"
        return [f"ltdl_solve_columns<Scalar, {self.nv}, {self.columns}{which}>(dof_tree, solve_L, solve_D_inv, {target});"]

    def loops(self):
        """The C++ statements after the terms: the looped CRBA and factor and the RNEA loop if any,
        solve, then copy each block into its output."""
        body = [] if self.factor is None else self.factor.loops()
        if self.low_rank:  # M⁻¹ first (with the tree's table): the RNEA loop's writer multiplies by it, and the feet's columns
            feet = [] if not self.feet_columns else [
                f"inverse_times_columns<Scalar, {self.nv}, {self.columns}, {2 * self.nv}, {self.feet_columns}>"
                f"({self.taken_inverse.output}, solve_rhs, {self.blocks[2][0]});"]
            return self.taken_inverse.loops() + self.rnea.loops(with_table=False) + feet
        body += [] if self.support is None else [self.support.place_table(column_support.PLACE)]
        body += [] if self.rnea is None else self.rnea.loops(with_table=self.factor is None)
        body += [dof_tree(self.parents)]
        body += (self._tree_solve("solve_rhs") if self.support is None
                 else self.support.loops(self.nv, self.columns, "solve_rhs"))
        body += [] if self.taken_inverse is None else self.taken_inverse.loops()
        return body + _copies(self.blocks, "solve_rhs", self.nv, self.columns, self.column_order)

    def emission(self, terms_name):
        if self.low_rank:
            return ("low-rank product: %s writes the bodies' transforms and the feet's right-hand sides, "
                    "articulated_inverse M⁻¹ by the articulated-body recursion (%d multiplications, where the "
                    "looped CRBA, ltdl_factor and ltdl_inverse would take %d), rnea_derivatives_loop's per-body "
                    "vectors times M⁻¹'s columns give ∂a/∂q and ∂a/∂v (InverseTimesVectors: running sums "
                    "along the chain, ∂τ never formed), inverse_times_columns the feet's %d columns (M⁻¹Jᵀ, %d "
                    "multiply-adds)" % (terms_name, *self.inverse.comparison, self.feet_columns,
                                        self.nv * self.nv * self.feet_columns))
        factor = (" and the factor" if self.factor is None else
                  ", crba_loop and ltdl_factor M's factor over a table of the tree (the looped CRBA and factor)")
        feet = " less the feet's ∂(Jᵀf)/∂q" if self.rnea is not None and self.rnea.feet else ""
        rnea = ("" if self.rnea is None else ", rnea_derivatives_loop subtracts ∂τ/∂(q, v)%s over the table "
                "(the RNEA's derivatives as a loop)" % feet)
        if self.taken_inverse is not None:
            rnea += (", ltdl_inverse writes ∂a/∂τ as M⁻¹'s rows Zᵀ D⁻¹ Z (%d multiply-adds where solving "
                     "Sᵀ's columns would take %d)" % self.inverse.comparison)
        elif self.inverse is not None:
            rnea += (", ∂a/∂τ solved with the rest (as M⁻¹'s rows Zᵀ D⁻¹ Z, %d multiply-adds against the "
                     "solve's %d for Sᵀ's columns)" % self.inverse.comparison)
        solve = "ltdl_solve_columns solves them all at once"
        if self.support is not None:
            solve = ("the columns sorted into %d blocks, ltdl_solve_column_range solves each, its L⁻ᵀ over "
                     "its columns' non-zero rows only (%d multiply-adds against %d over the whole tree)"
                     % (len(self.support.blocks), self.support.up_multiply_adds(), self.columns * self.factor_entries))
        return ("looped solve: %s writes the %d right-hand sides%s%s, %s, one SIMD row update per factor "
                "entry (%d)" % (terms_name, self.width, factor, rnea, solve, self.factor_entries))


@dataclass(frozen=True)
class LoopedContactSolve(LoopedSolve):
    """contact_dynamics_derivatives' columns (differentiate.contact_dynamics_derivative_terms) through
    M⁻¹'s halves (M = Lᵀ D L, Z = L⁻ᵀJᵀ: J M⁻¹ = (D⁻¹Z)ᵀ L⁻ᵀ, M⁻¹Jᵀ = L⁻¹ D⁻¹Z): Y = L⁻ᵀR1,
    B = (D⁻¹Z)ᵀ Y − R2 (= J M⁻¹R1 − R2), ∂λ = Q F⁻¹B = V (D⁻¹L⁻¹B) with Q = Σ_{j<PROXIMAL_STEPS} (μF⁻¹)ʲ
    (the proximal steps in closed form, DampedSolve.step_sum) and V = Q L⁻ᵀ formed once by loops
    (proximal_step_sum), ∂a = L⁻¹D⁻¹(Z∂λ − Y) (= M⁻¹Jᵀ∂λ − M⁻¹R1), each a loop over all columns. Z and
    D⁻¹Z are as sparse as J (a column is non-zero on its foot's path only) where M⁻¹Jᵀ is dense: the
    Mini Cheetah's products read 216 entries instead of 324. `blocks` are the ∂a outputs,
    `lambda_blocks` the ∂λ ones (same widths), `contact_rows` = 3·nc."""
    lambda_blocks: Tuple[Tuple[str, int], ...] = ()
    contact_rows: int = 0
    contact_columns: Tuple[Tuple[int, ...], ...] = ()  # per row of (D⁻¹Z)ᵀ, its non-zero columns
    dof_columns: Tuple[Tuple[int, ...], ...] = ()  # per row of Z (a dof), its non-zero columns

    def multiply_adds(self):
        m = self.contact_rows
        nonzeros = sum(map(len, self.contact_columns)) + sum(map(len, self.dof_columns))
        return super().multiply_adds() + nonzeros + _triangle(m) + m * m

    def _step_sum_columns(self):
        """V's rows are padded like the Delassus factor's halves'."""
        return differentiate.step_sum_columns(self.contact_rows)

    def _step_sum_multiply_adds(self):
        """V, formed once per call: G = (μL⁻ᵀ)(D⁻¹L⁻¹) over L⁻ᵀ's upper triangle, then PROXIMAL_STEPS − 1
        products V ← L⁻ᵀ + G V, all over V's padded columns."""
        m, p = self.contact_rows, self._step_sum_columns()
        return (_triangle(m) + (PROXIMAL_STEPS - 1) * m * m) * p

    def operations(self):
        """As the loops run them (checked by product/test_operation_counts.py): V's products start
        their sums from L⁻ᵀ (no addition for it), the two minus-products theirs from −R2 and −Y."""
        m, p, once = self.contact_rows, self._step_sum_columns(), self._step_sum_multiply_adds()
        ops = super().operations()
        return {"mul": ops["mul"] + once + m * p,                              # μL⁻ᵀ
                "add": ops["add"] + once,
                "neg": (m + self.nv) * self.columns}

    def instructions(self):
        m, p = self.contact_rows, self._step_sum_columns()
        runs = -(-p // SIMD_DOUBLES)
        return super().instructions() + m * p + runs * (2 * self._step_sum_multiply_adds() // p + (PROXIMAL_STEPS - 1) * m)

    def loops(self):
        n, m, c, p = self.nv, self.contact_rows, self.columns, self._step_sum_columns()
        return ([dof_tree(self.parents)] + self._tree_solve("solve_R1", "up")                # Y = L⁻ᵀR1
                + [row_sparsity("Zt_D_sparsity", self.contact_columns, lambda r, k: self._place("Zt_D", r * n + k)),
                   f"multiply_sparse_minus<Scalar, {m}, {n}, {c}>(Zt_D_sparsity, solve_Zt_D, solve_R1, solve_R2);",  # B
                   f"alignas(64) Scalar solve_V[{m * p}];",
                   f"proximal_step_sum<Scalar, {m}, {p}, {PROXIMAL_STEPS}>(solve_F_U, solve_F_DL, solve_mu[0], solve_V);",
                   f"alignas(64) Scalar solve_DL_B[{m * c}];",
                   f"multiply<Scalar, {m}, {m}, {c}, {p}, Triangle::lower>(solve_F_DL, solve_R2, solve_DL_B);",  # D⁻¹L⁻¹B
                   f"multiply<Scalar, {m}, {m}, {c}, {p}>(solve_V, solve_DL_B, solve_R2);",     # ∂λ in R2
                   row_sparsity("Z_sparsity", self.dof_columns, lambda i, r: self._place("Z", i * m + r)),
                   f"multiply_sparse_minus<Scalar, {n}, {m}, {c}>(Z_sparsity, solve_Z, solve_R2, solve_R1);"]  # Z∂λ − Y
                + self._tree_solve("solve_R1", "down")                                         # ∂a
                + _copies(self.blocks, "solve_R1", n, c, self.column_order)
                + _copies(self.lambda_blocks, "solve_R2", m, c, self.column_order))

    def emission(self, terms_name):
        return ("looped solve: %s writes the %d right-hand sides, Z = L⁻ᵀJᵀ and the factors; loops "
                "solve them all at once (M⁻¹'s halves with J M⁻¹ and M⁻¹Jᵀ between them, the Delassus "
                "system's proximal steps in closed form), one SIMD row update per entry" % (terms_name, self.width))


def _triangle(m):
    """The entries of an m × m triangle, diagonal included: a triangular factor's product reads only
    those (rbdc_gen::Triangle)."""
    return m * (m + 1) // 2


def dof_tree(parents, name="dof_tree"):
    """The C++ declaration of the rbdc_gen::DofTree `name` of the dof parents."""
    n = len(parents)
    ancestors = [dof_ancestors(parents, i) for i in range(n)]
    first = packed_starts(parents)
    deepest_first = list(range(n - 1, -1, -1))
    lists = column_support.below_lists(parents, deepest_first)
    below = lists[::-1]  # per dof its descendants and their entries, deepest first
    pairs = column_support.pairs_with_parent(parents, deepest_first, lists)[::-1]
    below_first = [0]
    for entries in below:
        below_first.append(below_first[-1] + len(entries))
    entries = max(first[-1], 1)  # no zero-size arrays: one unused entry

    def table(values, size):
        return "{" + ", ".join(map(str, list(values) + [0] * (size - len(values)))) + "}"

    tables = [table(first, n + 1), table([j for above in ancestors for j in above], entries),
              table(below_first, n + 1), table([i for column in below for i, _ in column], entries),
              table([k for column in below for _, k in column], entries),
              table(pairs, n), table(_pairs_with_child(parents), n)]
    return "RBDC_TABLE DofTree<%d, %d> %s{%s};" % (n, entries, name, ", ".join(tables))


def _pairs_with_child(parents):
    """1 where the L⁻¹ pass (root to leaves) solves row i together with its child's row i + 1, whose
    ancestors are i's and i: the pair reads i's ancestors once for both rows."""
    flags = [0] * len(parents)
    i = 0
    while i + 1 < len(parents):
        joined = parents[i + 1] == i
        flags[i] = int(joined)
        i += 2 if joined else 1
    return flags


def row_sparsity(name, columns, place):
    """The C++ declaration of the rbdc_gen::RowSparsity `name` of rows with non-zeros at `columns`,
    entry (r, k) stored at place(r, k), each row with the number of rows from it on that have its
    columns (the product sums those together)."""
    first = [0]
    for row in columns:
        first.append(first[-1] + len(row))
    flat = [k for row in columns for k in row] or [0]
    entries = [place(r, k) for r, row in enumerate(columns) for k in row] or [0]
    together = [1] * len(columns)  # the rows from r on with r's columns
    for r in range(len(columns) - 2, -1, -1):
        if columns[r] == columns[r + 1]:
            together[r] = together[r + 1] + 1
    return "RBDC_TABLE RowSparsity<%d, %d> %s{%s};" % (
        len(columns), len(flat), name, ", ".join("{%s}" % ", ".join(map(str, table))
                                                  for table in (first, flat, entries, together)))


def lane_places(entries, stored=lambda e: True):
    """Where a lane function's terms keep the `stored` entries of a matrix (row-major `entries`):
    each lane value whose lanes all appear, lanes 0, 1, … side by side from a multiple of ex.LANES
    (one vector store instead of a gather of lanes from several values: the Mini Cheetah's J and
    M⁻¹Jᵀ were 71 such gathers, docs/performance.md), then the other entries in order. Returns per
    entry its place, None where not stored."""
    lanes = {}  # lane value id -> {lane: entry}
    for index, e in enumerate(entries):
        if e.op == "lane_get" and stored(e):
            lanes.setdefault(e.args[0].id, {}).setdefault(e.value, index)
    place = [None] * len(entries)
    free = 0
    for group in lanes.values():
        if len(group) == ex.LANES:
            for lane in range(ex.LANES):
                place[group[lane]] = free + lane
            free += ex.LANES
    for index, e in enumerate(entries):
        if place[index] is None and stored(e):
            place[index] = free
            free += 1
    return tuple(place)


def _copies(blocks, source, rows, columns, order=()):
    """Each block's columns of the row-major `source` into its column-major output (copy_out_columns:
    per column of `source` where its rows go); with `order` (the logical column at each place), from
    where the order put them."""
    logical = list(order) + list(range(len(order), columns))
    destination = {}
    first = 0
    for name, width in blocks:
        for c in range(width):
            destination[first + c] = f"{name} + {rows * c}"
        first += width
    table = f"{source}_out"
    return [f"Scalar* const {table}[{columns}] = {{{', '.join(destination.get(c, 'nullptr') for c in logical)}}};",
            f"copy_out_columns<Scalar, {rows}, {columns}>({source}, {table});"]


def has_looped_form(robot, name):
    """Whether `name` has a looped form here; a coupled robot's forward_dynamics_derivatives solves
    in its independent coordinates, over their dof tree (passes/project.py). (Contact dynamics always
    has contacts: a scene without any is refused.)"""
    return name in TERMS and (not robot.couplings or name == "forward_dynamics_derivatives")


def looped_function(robot, scene, name, terms_name=None, rnea=False, factor=False, low_rank=False):
    """`name` in its looped form: the traced terms (function TERMS[name]; with `rnea` LOOP_TERMS[name],
    with `factor` too TREE_TERMS[name], with `low_rank` LOW_RANK_TERMS[name]; or `terms_name`, the lane
    function of one of them), with the loops as a LoopedSolve."""
    terms_name = terms_name or (LOW_RANK_TERMS[name] if low_rank else TREE_TERMS[name] if factor
                                else LOOP_TERMS[name] if rnea else TERMS[name])
    factor = factor or low_rank
    function = with_loop(robot, scene, name, terms_name,
                         lambda terms, outputs: _solve(robot, scene, name, terms, outputs, rnea or factor, factor,
                                                       low_rank))
    return replace(function, values=function.solve.placed(function.values))


def low_rank_applies(robot, scene, name):
    """Whether forward_dynamics_derivatives has the low-rank form here (InverseTimesVectors): a
    fixed-base chain of bodies alone (body_tree.applies), dofs numbered along it, where ∂a/∂τ is M⁻¹'s
    rows (looped_inverse.py), which the product needs."""
    return (name == "forward_dynamics_derivatives" and body_tree.fixed_base_chain(robot)
            and looped_inverse.tau_by_inverse(robot, 3 * len(scene.feet_for(robot)), differentiate.padded) is not None)


def _solve(robot, scene, name, terms, outputs, rnea=False, factor=False, low_rank=False):
    """The loops that solve the traced terms into the outputs of `name` (with `rnea`, after the
    looped RNEA derivatives complete them; with `factor`, with M's factor from the looped CRBA; with
    `low_rank`, ∂a/∂q and ∂a/∂v from M⁻¹ and the RNEA loop's vectors instead)."""
    parents = tuple(dof_parents(robot))
    if name == "contact_dynamics_derivatives":
        widths = {arg.name: arg.cols for arg in outputs}
        blocks = tuple((a, widths[a]) for a, _ in differentiate.CONTACT_COLUMNS)
        lambda_blocks = tuple((l, widths[l]) for _, l in differentiate.CONTACT_COLUMNS)
        m = 3 * len(scene.contacts_for(robot))
        Zt_D, Z = terms.values["Zt_D"], terms.values["Z"]  # row-major
        lanes = terms.lanes is not None
        order = lane_contact_derivatives.column_order(robot) if lanes else ()
        places = tuple((name, lane_places(terms.values[name], _non_zero)) for name in ("Zt_D", "Z")) if lanes else ()
        solve = LoopedContactSolve(parents=parents, blocks=blocks, terms=terms.outputs,
                                   lambda_blocks=lambda_blocks, contact_rows=m,
                                   contact_columns=_non_zero_columns(Zt_D, robot.nv),
                                   dof_columns=_non_zero_columns(Z, m), column_order=order, places=places)
    else:
        feet_rows = 3 * len(scene.feet_for(robot))
        inverse = None if terms.lanes is not None else looped_inverse.compared(robot, feet_rows, differentiate.padded)
        blocks = tuple((arg.name, arg.cols) for arg in outputs
                       if arg.cols and not (inverse is not None and inverse.pays and arg.name == inverse.output))
        from .looped_factor import LoopedFactor  # it imports this module's loops' header
        columns = differentiate.padded(sum(width for _, width in blocks))
        rhs, width = terms.outputs[0].name, sum(width for _, width in blocks)
        # the lane terms of the looped RNEA form keep the plain order (its loop subtracts from the first 2 nv)
        lane_order = lane_derivatives.column_order(robot, feet_rows) if terms.lanes is not None and not rnea else ()
        # a quadruped's lane order keeps each lane value's columns together, every limb in each run
        support = None if robot.couplings or lane_order != tuple(range(len(lane_order))) else \
            column_support.planned(parents, _column_rows(parents, terms.values[rhs], columns, width), columns)
        place = column_support.PLACE if support else ""
        # the feet's ∂(Jᵀf)/∂q rides on the RNEA loop's ∂τ/∂q entries
        subtract = looped_rnea_derivatives.subtracted_from(robot, terms.outputs, "solve_rhs", columns, place,
                                                           feet=bool(scene.feet_for(robot)))
        packed = LoopedFactor(parents=parents, terms=terms.outputs, unpack=False,
                              crba=looped_crba.LoopedCrba(robot=robot, terms=terms.outputs, packed=True))
        order = support.order if support else lane_order
        places = ((rhs, support.entry_places(len(parents), columns)),) if support else ()
        if low_rank:  # the traced part leaves ∂/∂q and ∂/∂v to the loop on a fixed base
            assert not any(_non_zero(e) for r in range(robot.nv)
                           for e in terms.values[rhs][r * columns:r * columns + 2 * robot.nv])
            subtract, support, order, places = (
                looped_rnea_derivatives.inverse_times_vectors(robot, terms.outputs, bool(scene.feet_for(robot))),
                None, (), ())
            by_factor = packed.operations()["mul"] + inverse.operations()["mul"]
            inverse = articulated_inverse.ArticulatedInverse(robot=robot, feet=articulated_inverse.chain_feet(robot, scene))
            inverse = replace(inverse, comparison=(inverse.operations()["mul"], by_factor))
        solve = LoopedSolve(parents=parents, blocks=blocks, terms=terms.outputs,
                            rnea=subtract if rnea else None, factor=packed if factor and not low_rank else None,
                            inverse=inverse, support=support, column_order=order, places=places,
                            low_rank=low_rank)
        assert [a.name for a in outputs] == list(differentiate.FORWARD_DYNAMICS_COLUMNS)
    assert terms.outputs[0].cols == solve.columns
    return solve


def _non_zero(entry):
    return not entry.is_const(0.0)


def _column_rows(parents, rhs, columns, width):
    """Per logical column of right-hand sides `rhs` (row-major, `columns` wide), the rows it may be
    non-zero on: its traced entries', and for ∂/∂q_j and ∂/∂v_j (the first 2 nv, which loops may
    write) j's and its descendants' (column_support.py)."""
    n = len(parents)
    descendants = [[] for _ in range(n)]
    for i in range(n):
        for j in dof_ancestors(parents, i):
            descendants[j].append(i)
    rows = [[r for r in range(n) if _non_zero(rhs[r * columns + c])] for c in range(width)]
    for c in range(min(2 * n, width)):
        rows[c] += [c % n] + descendants[c % n]
    return rows


def _non_zero_columns(entries, width):
    """Per row of a row-major matrix `width` columns wide, the columns of its non-zero entries."""
    return tuple(tuple(k for k in range(width) if _non_zero(entries[r * width + k]))
                 for r in range(len(entries) // width))
