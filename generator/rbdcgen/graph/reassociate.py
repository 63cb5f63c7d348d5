"""Sums added in the order their terms are ready: a pass after tracing that shortens the critical
path (graph/latency.py) and keeps the operation count (docs/performance.md, "Forms chosen by their
critical path too, and sums added in the order their terms arrive").

A traced algorithm writes a sum as its formula reads, ((a + b) − c) + d·e, each addition waiting on
the one before, though the terms arrive at different times: a body's force sums a term that is ready
early (its inertia times a constant) with one that waits on the whole chain above it. Where a sum's
inner sums are used by it alone, its terms may be added in any order, and this pass adds the two
that are ready first, again and again (Huffman's rule, optimal for costs of the form max + constant);
a product it may fuse into the addition counts as ready when its operands are. n terms still take
n − 1 additions and subtractions, so instruction counts do not change; the value differs from the
formula's order by round-off only. A negation needs no instruction: a term's sign picks between
addition and subtraction, and a positive term always remains to subtract the negative ones from."""

from __future__ import annotations

import heapq

from . import expr as ex
from .latency import time

_SUMS = ("add", "sub")


def reassociate(outputs):
    """`outputs` with every sum rebuilt in its terms' order of arrival (module doc)."""
    order = ex.reachable(outputs)
    if not order:
        return list(outputs)
    uses = ex.use_counts(order, outputs)
    inner = set()  # sums used once, by a sum: their terms join that sum's
    for node in order:
        if node.op in _SUMS:
            for arg in node.args:
                if arg.op in _SUMS and uses[arg.id] == 1 and arg.lane == node.lane:
                    inner.add(arg.id)
    graph = order[0].graph
    new, ready, operands = {}, {}, {}
    for node in order:
        if node.id in inner:
            continue
        graph.label, graph.position = node.label, node.position  # rewrites stand where node stood
        if node.op in _SUMS and (node.args[0].id in inner or node.args[1].id in inner):  # 3 terms or more
            terms = []
            _collect(node, True, inner, terms)
            rebuilt = _sum([(t, new[t.id], positive) for t, positive in terms], uses, ready, operands)
            if all(new[t.id] is t for t, _ in terms):  # keep the formula's tree unless later
                _time(node, ready, operands)
                if ready[node.id] <= ready[rebuilt.id]:
                    rebuilt = node
        else:
            args = tuple([new[a.id] for a in node.args])
            same = all(a is b for a, b in zip(args, node.args))
            rebuilt = node if same else graph.intern(node.op, args, node.value)
        new[node.id] = rebuilt
        if rebuilt.id not in ready:  # a sum's is timed by _sum, or with its inner sums above
            time(rebuilt, ready, operands)
    graph.label, graph.position = order[-1].label, None  # as after the last node's turn
    return [new[node.id] for node in outputs]


def _collect(node, positive, inner, terms):
    """The terms of the sum `node` with their signs, left to right, through its inner sums."""
    for k, arg in enumerate(node.args):
        sign = positive if node.op == "add" or k == 0 else not positive
        if arg.id in inner:
            _collect(arg, sign, inner, terms)
        else:
            terms.append((arg, sign))


def _sum(terms, uses, ready, operands):
    """The terms ((traced, rebuilt, sign)) added two at a time, the earliest two first. A product
    used by this sum alone is due when its operands are (it fuses into the addition); every other
    term when it is ready."""
    heap = []
    for k, (traced, term, positive) in enumerate(terms):
        fused = term.op == "mul" and uses.get(traced.id) == 1
        heapq.heappush(heap, (operands[term.id] if fused else ready[term.id], k, term, positive))
    count = len(heap)
    while len(heap) > 1:
        _, _, x, x_positive = heapq.heappop(heap)
        _, _, y, y_positive = heapq.heappop(heap)
        if x_positive == y_positive:
            total = ex.add(x, y)
        elif x_positive:
            total = ex.sub(x, y)
        else:
            total = ex.sub(y, x)
        if total.id not in ready:
            _time(total, ready, operands)
        heapq.heappush(heap, (ready[total.id], count, total, x_positive or y_positive))
        count += 1
    _, _, total, positive = heap[0]
    assert positive, "a sum's first term is positive, so a positive term remains"
    return total


def _time(node, ready, operands):
    """Times `node` and whatever it stands on that is not timed yet: folding (ex.sub of a negation)
    may build a node on one it built itself."""
    if node.id in ready:
        return
    for arg in node.args:
        _time(arg, ready, operands)
    time(node, ready, operands)
