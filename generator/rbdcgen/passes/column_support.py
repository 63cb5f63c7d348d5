"""The right-hand sides' own sparsity in the first half of forward_dynamics_derivatives' looped
solve (docs/performance.md, "Each block of columns on its own rows").

M⁻¹ = L⁻¹ D⁻¹ L⁻ᵀ, and L⁻ᵀ sums each row into its ancestors only: a column that is zero off a set of
rows closed under ancestors stays zero off it. ∂τ/∂q_j and ∂τ/∂v_j are non-zero on dof j's
ancestors and descendants only (a force below j or a motion above it), Sᵀ's column of dof j on j, a
foot's Jacobian column on the foot's path. On a humanoid such a set is one limb and the trunk above
it: taken eight columns at a time as Talos's outputs order them, L⁻ᵀ would visit 44 % of the factor
entries it visits over the whole tree (but a block of twelve such runs spans every limb). The
columns are sorted by the deepest of their rows (a limb's side by side), cut into blocks of whole
runs of RUN columns, and each block's L⁻ᵀ runs over the union of its columns' rows
(rbdc_gen::RowSubset, ltdl_solve_column_range). L⁻¹D⁻¹ fills every row, so the second half is as
before."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Tuple

from ..algorithms.forward_dynamics import dof_ancestors, packed_starts

PLACE = "solve_rhs_place"  # the C++ table of the logical columns' places
# Block bounds fall on multiples of this many columns: whole runs of every target
# (differentiate.ROW_ALIGNMENT).
RUN = 8
# rbdc_gen::LTDL_BLOCK_RUNS: the most runs a block's sums hold in registers (longer blocks are split by
# the C++, over the same rows).
BLOCK_RUNS = 12
# A block's row updates, per factor entry it visits, cost its runs' loads and multiply-adds and one
# load of the entry itself, which more runs share: weighed as this many runs. Nearly free: Talos's
# blocks of 4 and of 10 runs did 23 multiply-adds per ns alike, and its ∂q̈ took the same time with
# 0.25 and 0.5 (19.3 µs; clang 14, AMD EPYC Zen 4); the lower weight cuts finer blocks.
ENTRY_LOAD = 0.25
# Taken where the blocks' cost is at most this share of the whole tree's (a saving within noise is not
# worth the tables and the longer header).
PAYS_BELOW = 0.95


@dataclass(frozen=True)
class ColumnBlock:
    """Columns [first, end) of the sorted right-hand sides, zero off `rows` (deepest first)."""
    first: int
    end: int
    rows: Tuple[int, ...]


@dataclass(frozen=True)
class ColumnSupport:
    """The sorted right-hand sides: `order` the logical column at each place, `blocks` in order."""
    parents: Tuple[int, ...]
    order: Tuple[int, ...]
    blocks: Tuple[ColumnBlock, ...]

    def place(self):
        """Per logical column its place."""
        place = [0] * len(self.order)
        for at, logical in enumerate(self.order):
            place[logical] = at
        return tuple(place)

    def entry_places(self, rows, columns):
        """Where each entry of the row-major right-hand sides (`rows` × `columns`, logical order) goes."""
        place = self.place()
        return tuple(r * columns + place[c] for r in range(rows) for c in range(columns))

    def place_table(self, name):
        """The C++ table of each logical column's place, for the loops that write columns."""
        return "RBDC_TABLE int %s[%d] = {%s};" % (name, len(self.order), ", ".join(map(str, self.place())))

    def widths_and_entries(self):
        """Per block its columns and the factor entries among its rows (L⁻ᵀ's multiply-adds per column)."""
        return [(b.end - b.first, _entries(self.parents, b.rows)) for b in self.blocks]

    def up_multiply_adds(self):
        """L⁻ᵀ's multiply-adds over all columns: per column one per factor entry among its block's rows."""
        return sum(width * entries for width, entries in self.widths_and_entries())

    def loops(self, nv, columns, target):
        """The C++ statements: each block's rows as a table, then its solve."""
        out = []
        for k, block in enumerate(self.blocks):
            name = f"solve_rows_{k}"
            out.append(row_subset(self.parents, block.rows, name))
            out.append(f"ltdl_solve_column_range<Scalar, {nv}, {columns}, {block.first}, {block.end}>"
                       f"(dof_tree, {name}, solve_L, solve_D_inv, {target});")
        return out


def _entries(parents, rows):
    """The factor entries among `rows` (closed under ancestors: each row's ancestors are among them)."""
    return sum(len(dof_ancestors(parents, i)) for i in rows)


def below_lists(parents, rows):
    """Per row of `rows` (deepest first, closed under ancestors) its descendants among them, deepest
    first, each with its entry at the row in the packed factor."""
    at = {j: s for s, j in enumerate(rows)}
    first_entry = packed_starts(parents)
    below = [[] for _ in rows]
    for i in rows:
        for e, j in enumerate(dof_ancestors(parents, i)):
            below[at[j]].append((i, first_entry[i] + e))
    return below


def pairs_with_parent(parents, rows, below):
    """Per row of `rows` (deepest first) 1 where the L⁻ᵀ pass (leaves to root) solves row j together
    with its parent's row j − 1, the next one: the parent's descendants are then its others, j's, and
    j last (depth-first numbering), so the pair reads j's descendants once for both rows; greedily
    from the leaves, each row in one pair at most."""
    flags = [0] * len(rows)
    s = 0
    while s + 1 < len(rows):
        j, mine, theirs = rows[s], [i for i, _ in below[s]], [i for i, _ in below[s + 1]]
        joined = parents[j] == j - 1 and theirs[len(theirs) - len(mine) - 1:] == mine + [j]
        flags[s] = int(joined)
        s += 2 if joined else 1
    return flags


def row_subset(parents, rows, name):
    """The C++ declaration of the rbdc_gen::RowSubset `name` of `rows` (deepest first, closed under
    ancestors)."""
    below = below_lists(parents, rows)
    first = [0]
    for entries in below:
        first.append(first[-1] + len(entries))
    flat = [entry for entries in below for entry in entries] or [(0, 0)]  # no zero-size arrays

    def table(values):
        return "{" + ", ".join(map(str, values)) + "}"

    return "RBDC_TABLE RowSubset<%d, %d> %s{%s};" % (
        len(rows), len(flat), name, ", ".join([table(rows), table(first), table(i for i, _ in flat),
                                               table(k for _, k in flat),
                                               table(pairs_with_parent(parents, rows, below))]))


def _closed(parents, rows):
    """`rows` and their ancestors."""
    out = set(rows)
    for i in rows:
        out.update(dof_ancestors(parents, i))
    return out


def _partition(runs, cost):
    """The cheapest cut of `runs` runs into blocks of at most BLOCK_RUNS consecutive runs, `cost(first,
    end)` each: (its cost, its blocks as (first, end))."""
    best, cut = [0.0] + [None] * runs, [0] * (runs + 1)
    for end in range(1, runs + 1):
        best[end], cut[end] = min((best[first] + cost(first, end), first)
                                  for first in range(max(0, end - BLOCK_RUNS), end))
    blocks, end = [], runs
    while end > 0:
        blocks.append((cut[end], end))
        end = cut[end]
    return best[runs], blocks[::-1]


def planned(parents, column_rows, columns):
    """The ColumnSupport for right-hand sides `columns` wide whose logical column c is zero off
    column_rows[c] and their ancestors (the columns past them are padding, zero), or None where it
    does not pay."""
    n = len(parents)
    supports = [_closed(parents, rows) or {0} for rows in column_rows]
    supports += [set() for _ in range(columns - len(supports))]
    order = sorted(range(columns), key=lambda c: (max(supports[c], default=n), -len(supports[c])))
    runs = [set().union(*(supports[c] for c in order[r:r + RUN])) for r in range(0, columns, RUN)]
    depth = [len(dof_ancestors(parents, i)) for i in range(n)]
    whole = sum(depth)

    def cost(first, end, rows=None):
        rows = set().union(*runs[first:end]) if rows is None else rows
        return (end - first + ENTRY_LOAD) * (sum(depth[i] for i in rows) + whole)

    best, cut = _partition(len(runs), cost)
    if best > PAYS_BELOW * _partition(len(runs), lambda first, end: cost(first, end, range(n)))[0]:
        return None
    blocks = tuple(ColumnBlock(first * RUN, end * RUN, tuple(sorted(set().union(*runs[first:end]), reverse=True)))
                   for first, end in cut)
    return ColumnSupport(parents=tuple(parents), order=tuple(order), blocks=blocks)
