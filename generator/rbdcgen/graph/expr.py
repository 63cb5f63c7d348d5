"""Symbolic scalars: a hash-consed DAG of scalar operations with constant folding.

Every node lives in a `Graph`. Building a node first folds it (rules below), then looks up an
identical node in the graph's table, so structurally equal subexpressions are one node: common
subexpression elimination comes for free, and node ids (creation order) make the output
deterministic.

Folding rules never reassociate non-constant terms, so a folded expression evaluates to the
unfolded one up to round-off of the constants combined:
    x + 0 = x        x - 0 = x        0 - x = -x       x - x = 0
    x + (-y) = x - y (-x) + y = y - x x - (-y) = x + y  -(x - y) = y - x
    x * 0 = 0        x * 1 = x        x * (-1) = -x     (-x) * (-y) = x * y
    (-x) * y = -(x * y)               c1 * (c2 * x) = (c1 * c2) * x
    x / 1 = x        0 / x = 0        -(-x) = x
    c1 op c2, sin(c), cos(c), sqrt(c) evaluate to constants.
Commutative operands (+, *) are ordered (constants first, then by node id) so that a + b and
b + a are one node.

Lanes (docs/performance.md, "One SIMD lane per leg"): symbols of an array named `lane_*` hold one
value per lane (4 isomorphic limbs evaluated together, rbdcgen/lanes.py); every operation with a lane
operand is a lane operation (scalar operands broadcast), except `lane_sum` (the sum over the lanes,
a scalar) and `lane_get` (one lane, `value` its index). Constants that differ between lanes are
such symbols (lane_const), so folding (x·0, x·1, …) only applies where all lanes agree; an operation
on constants and lane constants folds to a lane constant.

Nodes carry the graph's `label` at their creation (set_label), which the emitter prints as markers,
and a `position`: their id, or for a node rewritten after tracing the id of the node it replaces, so
that sorting by (position, id) is a topological order that follows the algorithm.
"""

from __future__ import annotations

import gc
import math
import operator
import threading

# Operation names. "const" and "sym" are leaves; the rest are the emitted operations.
UNARY = ("neg", "sin", "cos", "sqrt")
LANE_ARRAY_PREFIX = "lane_"  # symbols of these arrays are lane values
LANES = 4  # lanes per lane value: one AVX register of doubles
LANE_CONSTANTS = "lane_c"  # the array of lane constants (lane_const)
BINARY = ("add", "sub", "mul", "div")
COMMUTATIVE = ("add", "mul")

_state = threading.local()


class Graph:
    """The node table of one traced function. Use as a context manager around tracing."""

    def __init__(self):
        self._table = {}
        self.nodes = []
        self.label = None  # where in the algorithm new nodes come from (set_label)
        self.position = None  # where a rewritten node stands in creation order (absorb_negations)
        self.lane_constants = []  # values of lane constant k (symbol lane_c[k]): LANES floats
        self._lane_constant_index = {}
        self.reachable_orders = {}  # output ids → reachable(outputs)

    def __enter__(self):
        self._outer = getattr(_state, "graph", None)
        _state.graph = self
        # Tracing makes a node per operation, all alive as long as the graph: the cyclic collector
        # would walk them again and again and free nothing (a 200-body chain's OSC: 2 s of 6).
        self._collecting = gc.isenabled()
        gc.disable()
        return self

    def __exit__(self, *exc):
        _state.graph = self._outer
        if self._collecting:
            gc.enable()
        return False

    def intern(self, op, args, value):
        # Keys by arity without a generator (this runs for every node traced): lengths or types differ.
        if len(args) == 2:
            key = (op, args[0].id, args[1].id, value)
        elif len(args) == 1:
            key = (op, args[0].id, value)
        else:
            key = (op, tuple(a.id for a in args), value)
        node = self._table.get(key)
        if node is None:
            node = self.new_node(op, args, value)
            self._table[key] = node
        return node

    def new_node(self, op, args, value):
        node = Expr(op, args, value, len(self.nodes), self, self.label)
        node.position = node.id if self.position is None else self.position
        if op == "sym":
            node.lane = value[0].startswith(LANE_ARRAY_PREFIX)
        else:
            node.lane = op not in ("lane_sum", "lane_get") and _any_lane(args)
        self.nodes.append(node)
        return node


def current_graph():
    graph = getattr(_state, "graph", None)
    if graph is None:
        raise RuntimeError("rbdcgen.expr: build expressions inside a `with Graph():` block")
    return graph


def set_label(label):
    """Tags the nodes created from now on with `label` (e.g. "outward pass: body 3 LF_knee")."""
    current_graph().label = label


class Expr:
    """One node. `value` is the float of a constant or the (array, index) of a symbol; `lane` tells
    whether it holds one value per lane."""

    __slots__ = ("op", "args", "value", "id", "graph", "label", "position", "lane")

    def __init__(self, op, args, value, node_id, graph, label=None):
        self.op = op
        self.args = args
        self.value = value
        self.id = node_id
        self.graph = graph
        self.label = label

    def __repr__(self):
        if self.op == "const":
            return repr(self.value)
        if self.op == "sym":
            return "%s[%d]" % self.value
        return "%s(%s)" % (self.op, ", ".join(repr(a) for a in self.args))

    # Python operators route through the folding constructors below.
    def __add__(self, other):
        return add(self, lift(other))

    def __radd__(self, other):
        return add(lift(other), self)

    def __sub__(self, other):
        return sub(self, lift(other))

    def __rsub__(self, other):
        return sub(lift(other), self)

    def __mul__(self, other):
        return mul(self, lift(other))

    def __rmul__(self, other):
        return mul(lift(other), self)

    def __truediv__(self, other):
        return div(self, lift(other))

    def __rtruediv__(self, other):
        return div(lift(other), self)

    def __neg__(self):
        return neg(self)

    def __pos__(self):
        return self

    def is_const(self, value=None):
        return self.op == "const" and (value is None or self.value == value)

    __hash__ = object.__hash__


def const(value):
    value = float(value)
    if not math.isfinite(value):
        raise ValueError("rbdcgen.expr: non-finite constant %r" % value)
    if value == 0.0:
        value = 0.0  # one zero: -0.0 and 0.0 are the same node
    return current_graph().intern("const", (), value)


def lane_const(values):
    """A constant with one value per lane: the symbol lane_c[k], or an ordinary constant when the
    lanes agree (so that folding applies exactly where it would in every lane)."""
    values = tuple(0.0 if v == 0.0 else float(v) for v in values)
    if all(v == values[0] for v in values):
        return const(values[0])
    graph = current_graph()
    if values not in graph._lane_constant_index:
        graph._lane_constant_index[values] = len(graph.lane_constants)
        graph.lane_constants.append(values)
    return symbol(LANE_CONSTANTS, graph._lane_constant_index[values])


def constant_lanes(x):
    """x's value in each lane if x is a constant or a lane constant, else None."""
    if x.op == "const":
        return (x.value,) * LANES
    if x.op == "sym" and x.value[0] == LANE_CONSTANTS:
        return x.graph.lane_constants[x.value[1]]
    return None


def joint_angle(node):
    """(input symbol, offset) of a joint angle as the sines take it: q_k (offset None), or q_k + φ with
    φ a constant or a lane constant (a body turned about its axis, views/turns.py); else None."""
    if node.op == "sym" and node.value[0] != LANE_CONSTANTS:
        return node, None
    if node.op == "add":
        for symbol, offset in (node.args, node.args[::-1]):
            if symbol.op == "sym" and symbol.value[0] != LANE_CONSTANTS and constant_lanes(offset) is not None:
                return symbol, offset
    return None


def _any_lane(args):
    """Whether any of the nodes `args` is a lane value (a loop: `any` over a generator costs more for
    one or two operands, and this runs for every node traced)."""
    for a in args:
        if a.lane:
            return True
    return False


def _fold_lanes(function, *args):
    """function over floats applied lane by lane when every operand is constant and one of them a
    lane constant (the folding of `c1 op c2` for lanes), else None."""
    if not _any_lane(args):
        return None
    lanes = [constant_lanes(a) for a in args]
    if any(v is None for v in lanes):
        return None
    return lane_const(function(*(v[k] for v in lanes)) for k in range(LANES))


def symbol(array, index):
    """The input scalar `array[index]` of the traced function."""
    return current_graph().intern("sym", (), (array, int(index)))


def lift(x):
    return x if isinstance(x, Expr) else const(x)


def _order_key(node):
    return (node.op != "const", node.id)


def _node(op, *args):
    if op in COMMUTATIVE and _order_key(args[0]) > _order_key(args[1]):
        args = (args[1], args[0])
    return args[0].graph.intern(op, args, None)


def neg(x):
    if x.lane:
        folded = _fold_lanes(operator.neg, x)
        if folded is not None:
            return folded
    if x.op == "const":
        return const(-x.value)
    if x.op == "neg":
        return x.args[0]
    if x.op == "sub":
        return sub(x.args[1], x.args[0])
    return _node("neg", x)


def add(x, y):
    if x.op == "const" and y.op == "const":
        return const(x.value + y.value)
    if x.lane or y.lane:
        folded = _fold_lanes(operator.add, x, y)
        if folded is not None:
            return folded
    if y.is_const(0.0):
        return x
    if x.is_const(0.0):
        return y
    if y.op == "neg":
        return sub(x, y.args[0])
    if x.op == "neg":
        return sub(y, x.args[0])
    return _node("add", x, y)


def sub(x, y):
    if x.op == "const" and y.op == "const":
        return const(x.value - y.value)
    if x.lane or y.lane:
        folded = _fold_lanes(operator.sub, x, y)
        if folded is not None:
            return folded
    if x is y:
        return const(0.0)
    if y.is_const(0.0):
        return x
    if x.is_const(0.0):
        return neg(y)
    if y.op == "neg":
        return add(x, y.args[0])
    if x.op == "neg":
        return neg(add(x.args[0], y))
    return _node("sub", x, y)


def mul(x, y):
    if x.op == "const" and y.op == "const":
        return const(x.value * y.value)
    if x.lane or y.lane:
        folded = _fold_lanes(operator.mul, x, y)
        if folded is not None:
            return folded
    if y.op == "const":
        x, y = y, x
    if x.op == "const":
        if x.value == 0.0:
            return x
        if x.value == 1.0:
            return y
        if x.value == -1.0:
            return neg(y)
        if y.op == "neg":
            return mul(const(-x.value), y.args[0])
        if y.op == "mul" and y.args[0].op == "const":
            return mul(const(x.value * y.args[0].value), y.args[1])
        if x.value < 0.0:
            return neg(mul(const(-x.value), y))
        return _node("mul", x, y)
    if x.op == "neg" and y.op == "neg":
        return mul(x.args[0], y.args[0])
    if x.op == "neg":
        return neg(mul(x.args[0], y))
    if y.op == "neg":
        return neg(mul(x, y.args[0]))
    return _node("mul", x, y)


def div(x, y):
    if x.lane or y.lane:
        folded = _fold_lanes(operator.truediv, x, y)
        if folded is not None:
            return folded
    if y.op == "const":
        if y.value == 0.0:
            raise ZeroDivisionError("rbdcgen.expr: division by the constant 0")
        if x.op == "const":
            return const(x.value / y.value)
        if y.value == 1.0:
            return x
        if y.value == -1.0:
            return neg(x)
    if x.is_const(0.0):
        return x
    if x.op == "neg":
        return neg(div(x.args[0], y))
    if y.op == "neg":
        return neg(div(x, y.args[0]))
    return _node("div", x, y)


def sin(x):
    return const(math.sin(x.value)) if x.op == "const" else _node("sin", x)


def cos(x):
    return const(math.cos(x.value)) if x.op == "const" else _node("cos", x)


def sqrt(x):
    if x.op == "const":
        return const(math.sqrt(x.value))
    return _node("sqrt", x)


def lane_sum(x):
    """The scalar sum of the lanes of x (4·x for a value the lanes share; folded for a constant)."""
    if not x.lane:
        return mul(const(float(LANES)), x)
    values = constant_lanes(x)
    return _node("lane_sum", x) if values is None else const(sum(values))


def lane_get(x, lane):
    """Lane `lane` of x as a scalar (x itself when it is no lane value); of a rotated value, the lane
    it came from (no shuffle)."""
    if x.op == "lane_rotate":
        return lane_get(x.args[0], (lane + x.value) % LANES)
    if x.op == "neg" and x.args[0].op == "lane_rotate":
        return neg(lane_get(x.args[0], lane))
    return x.graph.intern("lane_get", (x,), int(lane)) if x.lane else x


def lane_rotate(x, shift):
    """x with its lanes rotated: lane k holds lane (k + shift) mod LANES of x (one shuffle)."""
    shift %= LANES
    if not x.lane or shift == 0:
        return x
    values = constant_lanes(x)
    if values is not None:
        return lane_const(values[(k + shift) % LANES] for k in range(LANES))
    if x.op == "neg":  # outside, where a sum can take it as a subtraction
        return neg(lane_rotate(x.args[0], shift))
    return x.graph.intern("lane_rotate", (x,), shift)


def pack_lane_halves(low, high):
    """low's lanes 0-1 and high's lanes 2-3 in one lane value (a limb pair's spare lanes)."""
    return low * lane_const((1.0, 1.0, 0.0, 0.0)) + high * lane_const((0.0, 0.0, 1.0, 1.0))


def swap_lane_halves(x):
    """x with lanes 0-1 and 2-3 exchanged (a limb pair's spare lanes, views/limb_lanes.spare_lanes)."""
    return lane_rotate(x, LANES // 2)


def reachable(outputs):
    """Nodes reaching `outputs` (dead-code elimination), in a deterministic topological order:
    depth-first post-order, operands before users, outputs visited in the given order. Kept per
    graph and outputs (nodes never change, so neither does the order): tracing, scheduling, counting
    and emitting each ask for it; callers only read it."""
    if not outputs:
        return []
    cache = outputs[0].graph.reachable_orders
    key = tuple(root.id for root in outputs)
    if key not in cache:
        cache[key] = _depth_first_post_order(outputs)
    return cache[key]


def _depth_first_post_order(outputs):
    seen = set()
    order = []
    for root in outputs:
        if root.id in seen:
            continue
        seen.add(root.id)
        stack = [(root, iter(root.args))]   # each node with the operands it has yet to visit
        while stack:
            node, operands = stack[-1]
            for arg in operands:
                if arg.id not in seen:
                    seen.add(arg.id)
                    stack.append((arg, iter(arg.args)))
                    break
            else:
                stack.pop()
                order.append(node)
    return order


def use_counts(order, outputs):
    """{node id: its uses} over `order` (reachable(outputs)), each output counted once more."""
    uses = {}
    for node in order:
        for arg in node.args:
            uses[arg.id] = uses.get(arg.id, 0) + 1
    for node in outputs:
        uses[node.id] = uses.get(node.id, 0) + 1
    return uses


def absorb_negations(outputs):
    """Final peephole after tracing: a negation whose operand is a single-use product or sum that
    can take the sign for free disappears: −(c·y) = (−c)·y, −(x·y) = (−x)·y, −(x/y) = (−x)/y,
    −(x + y) = (−x) − y,
    recursively, where −x is itself free (a constant, a negation, a single-use subtraction, …).
    Folding keeps constants positive so that c·y and −c·y share one product; only once the DAG is
    complete do we know which products are used under a negation alone. Sign flips are exact."""
    order = reachable(outputs)
    uses = use_counts(order, outputs)
    new = {}

    def intern(op, args, value=None):
        return args[0].graph.intern(op, args, value) if args else const(value)

    def free_negation(node):
        """The rewritten −node if it costs no operation, else None (node already rewritten)."""
        if node.op == "const":
            return const(-node.value)
        if node.op == "neg":
            return node.args[0]
        if uses.get(node.id) != 1:  # a node this pass rebuilt: its uses unknown, keep it
            return None
        if node.op == "sub":
            return intern("sub", (node.args[1], node.args[0]))
        if node.op not in ("mul", "div", "add"):
            return None
        for k in (0, 1):
            negated = free_negation(node.args[k])
            if negated is None:
                continue
            other = node.args[1 - k]
            if node.op == "mul":
                return _node("mul", negated, other)
            if node.op == "div":
                return intern("div", (negated, other) if k == 0 else (other, negated))
            if node.op == "add":
                return intern("sub", (negated, other))
        return None

    graph = outputs[0].graph if outputs else None
    for node in order:  # (this runs for every node: no generators)
        args = tuple([new[a.id] for a in node.args])
        changed = False
        for a, b in zip(args, node.args):
            if a is not b:
                changed = True
                break
        if node.op == "neg" or changed:
            graph.label, graph.position = node.label, node.position  # rewrites stand where node stood
        rewritten = free_negation(args[0]) if node.op == "neg" else None
        if rewritten is not None:
            new[node.id] = rewritten
        elif changed:
            new[node.id] = intern(node.op, args, node.value)
        else:
            new[node.id] = node
    if graph is not None:
        graph.label, graph.position = order[-1].label, None  # as after the last node's turn
    return [new[node.id] for node in outputs]


_EVAL = {
    "neg": lambda a: -a,
    "add": lambda a, b: a + b,
    "sub": lambda a, b: a - b,
    "mul": lambda a, b: a * b,
    "div": lambda a, b: a / b,
    "sin": math.sin,
    "cos": math.cos,
    "sqrt": math.sqrt,
}


def _lanewise(function, args):
    """function over floats applied lane by lane where an argument is a lane value (a tuple)."""
    if not any(isinstance(a, tuple) for a in args):
        return function(*args)
    return tuple(function(*(a[k] if isinstance(a, tuple) else a for a in args)) for k in range(LANES))


def evaluate(outputs, inputs):
    """Numeric value of each node in `outputs` given `inputs` = {array name: list of floats}; a
    lane array holds a tuple of LANES floats per entry. The reference evaluator for tests and
    debugging."""
    values = {}
    for node in reachable(outputs):
        if node.op == "const":
            values[node.id] = node.value
        elif node.op == "sym":
            array, index = node.value
            value = inputs[array][index]
            values[node.id] = tuple(map(float, value)) if node.lane else float(value)
        elif node.op == "lane_sum":
            x = values[node.args[0].id]
            values[node.id] = (x[0] + x[1]) + (x[2] + x[3])
        elif node.op == "lane_get":
            values[node.id] = values[node.args[0].id][node.value]
        elif node.op == "lane_rotate":
            x = values[node.args[0].id]
            values[node.id] = tuple(x[(k + node.value) % LANES] for k in range(LANES))
        else:
            values[node.id] = _lanewise(_EVAL[node.op], [values[a.id] for a in node.args])
    return [values[node.id] for node in outputs]
