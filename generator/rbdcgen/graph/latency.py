"""The critical path of a traced function: the longest chain of dependent operations from its inputs
to an output, in cycles of a current x86 core. No schedule of the same operations, by any compiler or
out-of-order core, computes one call in less: it bounds the latency of a call as the operation count
bounds its throughput (docs/performance.md, "The critical path").

The model (AMD Zen 4 and Zen 5, Intel from Skylake on, double and float alike): an addition,
subtraction or multiplication takes LATENCY cycles; an addition or subtraction of a product may
instead be one FMA, FMA cycles from the product's operands, whichever is sooner (g++ contracts
`a * b + c` across statements, even where the product has other uses); a negation is free (folded into
the FMA's sign or an xor off the path); a division and a square root take theirs; a joint angle's
sine and cosine come from `joint_sincos`'s polynomial (JOINT_SINCOS). Lane operations take their
scalar latency; a lane's extraction a shuffle; the sum over the lanes two additions and two
shuffles. The loops of a looped form (fn.solve and the other loop kernels) are not traced, so for
those forms this is the bound of the traced part alone."""

from __future__ import annotations

from . import expr as ex

LATENCY = {"add": 3, "sub": 3, "mul": 3, "div": 13, "sqrt": 15, "neg": 0,
           "lane_get": 1, "lane_rotate": 1, "lane_sum": 8}
FMA = 4
# The fold about ±π (a subtraction, a min and a max) and two polynomials of degree 7 by Estrin's
# scheme, by the latencies above: under the 36-37 cycles its chain takes in registers on Zen 5
# (tools/trig_latency.py), so still a lower bound.
JOINT_SINCOS = 27


def critical_path(fn):
    """Cycles of the longest dependent chain of fn's traced DAG (fn.output_exprs())."""
    return critical_path_of(fn.output_exprs())


def critical_path_of(outputs):
    ready = {}     # node id -> cycle its value is ready
    operands = {}  # a product's id -> cycle its operands are ready (an FMA's start)
    for node in ex.reachable(outputs):
        time(node, ready, operands)
    return max([ready[o.id] for o in outputs], default=0)


def time(node, ready, operands):
    """Records when `node` is ready (and a product's operands) in `ready` and `operands`, which hold
    its operands' already; returns it. (Written out: it runs for every node of every traced form.)"""
    op, args = node.op, node.args
    if op == "const" or op == "sym":
        at = 0
    elif op == "sin" or op == "cos":
        at = (0 if args[0].op == "sym" else ready[args[0].id]) + JOINT_SINCOS
    elif op == "add" or op == "sub":
        x, y = args
        x_at, y_at = ready[x.id], ready[y.id]
        at = (x_at if x_at > y_at else y_at) + LATENCY[op]  # the products computed first
        if x.op == "mul":  # or as an FMA of a product with the other operand
            at = min(at, max(operands[x.id], y_at) + FMA)
        if y.op == "mul":
            at = min(at, max(operands[y.id], x_at) + FMA)
    else:
        at = max([ready[a.id] for a in args], default=0) + LATENCY.get(op, 0)
        if op == "mul":
            operands[node.id] = at - LATENCY["mul"]
    ready[node.id] = at
    return at
