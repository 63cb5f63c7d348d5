"""Back end of the middle: a traced Function's DAG as straight-line C++ statements.

The statements are the body of
    template <class Scalar> void NAME(const Scalar* q, …, Scalar* out, …) noexcept
Inputs are read as `q[k]`, each output entry is written exactly once as `M[k] = …;` (column-major,
zeros and mirrored entries included). sin/cos of the joint angles come first, in one block: the
angles are gathered into an array and `joint_sincos` (rbdc_gen/support.hpp) computes them all at once
(a vectorised polynomial for double and float), named by joint (`sin_LF_knee`); then
every node used more than once becomes `Scalar tN = …;` in the order the algorithm created them
(expr.Expr.position, kept topological), and nodes used once are inlined into their single user, up
to MAX_INLINE_OPS operations per expression. Each output entry is stored right after the last
temporary it needs (constant entries first), so its operands need not stay live to the end of the
function: outputs must not overlap inputs
(docs/generated_api.md). The trailing run of stores is headed by `// outputs`. A comment
names the phase of the algorithm (expr labels: `// outward pass: body 3 LF_knee`) where it changes.
Constants print in their shortest round-trip form and a negative constant operand of + or − flips
the operator (`x + Scalar(0.5)`, never `x - Scalar(-0.5)`). Same DAG in, same text out.

A lane function (fn.lanes, views/limb_lanes.py) also declares `Lane = Lanes<Scalar>` (rbdc_gen/lanes.hpp),
its lane inputs and constants as arrays `lane_v[…]`, `lane_c[…]` of make_lanes(…), loads the sin/cos
of a lane angle from ex.LANES consecutive joint_trig entries, declares lane temporaries `Lane`,
reads lane k of a lane value as `t7[k]`, writes the runs where each limb's entries are the same lanes
of several lane values (a leg's column of M) transposed, `store_transposed_lanes<6>({M + 144, …},
{t21, …});` (`store_interleaved_lanes<3>(M + 6, {t73, …})` where the limbs' runs follow one
another), and each other run of ex.LANES consecutive output entries with one vector store,
`store_lanes(M + 8, make_lanes(…));` (of the lane value itself where the run holds its lanes in order),
unless a scalar or a constant sits among its computed values: those entries are stored one by one.

No local is const: g++'s scalar replacement of aggregates skips const locals, so where Scalar or Lane
is a class (a Pack of states, a lane vector) every const value stayed in memory, and g++ -O3 spent
its time walking the aliases of thousands of stores (humanoid32's ∂q̈ terms on Batch<double>: 37 s,
9 s without const)."""

from __future__ import annotations

import itertools

from ..graph import expr as ex

_BINARY_SYMBOL = {"add": "+", "sub": "-", "mul": "*", "div": "/"}
# A single-use node whose inlined text would hold more operations than this gets a temporary
# anyway: readable lines and bounded recursion for long chains (e.g. sums over many children).
MAX_INLINE_OPS = 12
ANGLES_PER_LINE = 8  # entries per line of the joint angle array


def format_constant(value):
    """The double in its shortest form that reads back exactly (Python's repr), whole numbers
    without a fraction.

    >>> format_constant(0.049), format_constant(1e-05), format_constant(2.0), format_constant(-1e+16)
    ('Scalar(0.049)', 'Scalar(1e-05)', 'Scalar(2)', 'Scalar(-1e+16)')
    """
    return "Scalar(%s)" % repr(value).removesuffix(".0")


def _is_negative_const(node):
    return node.op == "const" and node.value < 0.0


def _signed_operands(node):
    """(left, symbol, right) of a + or − node, the sign of a negative constant operand folded into
    the operator: x − (−c) → x + c, x + (−c) → x − c, (−c) + x → x − c (right is then the float c).
    Same value, same cost."""
    x, y = node.args
    symbol = _BINARY_SYMBOL[node.op]
    if node.op == "add" and _is_negative_const(x) and not _is_negative_const(y):
        x, y = y, x
    if _is_negative_const(y):
        return x, "-" if symbol == "+" else "+", -y.value
    return x, symbol, y


def _is_joint_trig(node):
    return node.op in ("sin", "cos") and ex.joint_angle(node.args[0]) is not None


def _angle_symbol(angle):
    """The input symbol of a joint angle (q_k or q_k + φ: expr.joint_angle)."""
    return ex.joint_angle(angle)[0]


def _angle_offsets(angle):
    """A joint angle's offset in each lane (0 without): two joints coupled one to one may share q_k,
    each with its own."""
    offset = ex.joint_angle(angle)[1]
    return (0.0,) * ex.LANES if offset is None else ex.constant_lanes(offset)


def schedule(fn):
    """(trig block, ordered temporaries, use counts) of the function's live DAG."""
    outputs = fn.output_exprs()
    order = ex.reachable(outputs)
    uses = ex.use_counts(order, outputs)
    trig = sorted((n for n in order if _is_joint_trig(n)),
                  key=lambda n: (_angle_symbol(n.args[0]).value, _angle_offsets(n.args[0]), n.op == "cos"))
    angles = {n.args[0].id for n in trig}  # written into joint_sincos's array, never a statement
    temp_ids = set()
    size = {}  # operations in a node's inlined text
    for n in order:  # (this runs for every node: no calls it can do without)
        op = n.op
        # a lane_get is read where used: its lane value stays live instead (one register, not one per
        # lane), and no view's late extraction holds it to the end
        if op == "const" or op == "sym" or op == "lane_get" or _is_joint_trig(n) or n.id in angles:
            size[n.id] = 0
            continue
        inlined = 1
        for a in n.args:
            inlined += size[a.id]
        while inlined > MAX_INLINE_OPS:
            largest = max(n.args, key=lambda a: size[a.id])  # give it its own statement
            temp_ids.add(largest.id)
            size[largest.id] = 0
            inlined = 1 + sum([size[a.id] for a in n.args])
        size[n.id] = inlined
        if uses[n.id] > 1:
            temp_ids.add(n.id)
            size[n.id] = 0
    # In the order the algorithm created them, so that its phases read top to bottom. A node's place
    # is its creation position, moved after its operands' places where a rewrite reused a later node;
    # ties keep the depth-first order, so operands still come first.
    place = {}
    for index, n in enumerate(order):
        at = n.position
        for a in n.args:
            if a.op != "const" and a.op != "sym" and place[a.id][0] > at:
                at = place[a.id][0]
        place[n.id] = (at, index)
    temps = sorted((n for n in order if n.id in temp_ids), key=lambda n: place[n.id])
    return trig, temps, uses


def _trig_block(trig, names, text, angle_names, lanes=None):
    """Statements computing the joint sin/cos nodes `trig` in one joint_sincos call; names each node
    after its joint (`sin_LF_knee`, angle_names: input symbol → identifier), else `sin_q_7`.
    A lane angle (`lanes`: the function's LaneLayout) takes its distinct lanes' consecutive entries
    (ex.LANES, or a pair's 2 repeated to fill the lanes: half the sines and cosines), so its sin and
    cos are loaded as one lane value; the widest lane angles come first, so their slots are aligned."""
    if not trig:
        return []

    def width(angle):
        return lanes.distinct_lanes(*_angle_symbol(angle).value) if angle.lane else 0

    angles = {node.args[0].id: node.args[0] for node in trig}
    slot = {}  # angle symbol id -> its index in joint_angle
    entries = []
    full = []  # the full-width lane angles' sources, in slot order
    pairs = []  # (slot, sources) of the lane angles of a limb pair
    lane_offsets = {}  # entry -> the offset its lane angle adds there
    for angle in sorted(angles.values(), key=lambda a: -width(a)):  # stable: trig order otherwise
        slot[angle.id] = len(entries)
        if angle.lane:
            symbol = _angle_symbol(angle).value
            sources = lanes.inputs[symbol[0]][symbol[1]]
            if width(angle) == 2:
                pairs.append((len(entries), sources[:2]))
            for l, offset in enumerate(_angle_offsets(angle)[:width(angle)]):
                if offset != 0.0:  # a turned limb's (views/turns.py): added after the lanes are stored
                    lane_offsets[len(entries) + l] = offset
            entries += ["%s[%d]" % source for source in sources[:width(angle)]]
            if width(angle) == ex.LANES:
                full.append(sources)
        else:
            entries.append(text(angle, False))
    n = len(entries)
    block = _transposition(full) if full else None
    runs = _pair_runs(pairs)
    if block or runs:  # the lanes' angles as whole vectors, the rest one by one
        stored = ex.LANES * len(full) if block else 0
        lines = ["// sines and cosines of the joint angles", "Scalar joint_angle[%d];" % n]
        if block:
            lines += ["store_lanes(joint_angle + %d, transposed_lanes<%d, %d>(%s + %d));"
                      % (ex.LANES * j, len(full), j, block[0], block[1]) for j in range(len(full))]
        covered = set(range(stored))
        for start, count, (a, b) in runs:
            lines.append("store_interleaved_pairs<%d>(joint_angle + %d, %s + %d, %s + %d);"
                         % (count, start, a[0], a[1], b[0], b[1]))
            covered |= set(range(start, start + 2 * count))
        lines += ["joint_angle[%d] = %s;" % (k, _offset(entries[k], lane_offsets.get(k, 0.0)))
                  for k in range(n) if k not in covered]
        lines += ["joint_angle[%d] %s= %s;" % (k, *_signed(x)) for k, x in sorted(lane_offsets.items()) if k in covered]
    else:
        entries = [_offset(entry, lane_offsets.get(k, 0.0)) for k, entry in enumerate(entries)]
        rows = [", ".join(entries[i:i + ANGLES_PER_LINE]) for i in range(0, n, ANGLES_PER_LINE)]
        lines = ["// sines and cosines of the joint angles",
                 "Scalar joint_angle[%d] = {%s};" % (n, (",\n    ").join(rows))]
    lines.append("auto joint_trig = joint_sincos(joint_angle);")
    suffix = {}  # angle id -> "", "_2", …: the angles of one input symbol in trig's order
    named = {}  # input symbol -> how many of its angles have a name
    for node in trig:
        angle = node.args[0]
        symbol = _angle_symbol(angle).value
        if angle.id not in suffix:
            named[symbol] = named.get(symbol, 0) + 1
            suffix[angle.id] = "_%d" % named[symbol] if named[symbol] > 1 else ""
        name = "%s_%s%s" % (node.op, angle_names.get(symbol) or "%s_%d" % symbol, suffix[angle.id])
        if node.lane:
            load = ("load_lanes" if width(angle) == ex.LANES
                    else "load_repeated_lanes<%d>" % width(angle))
            lines.append("Lane %s = %s(joint_trig.%s + %d);" % (name, load, node.op, slot[angle.id]))
        else:
            lines.append("Scalar %s = joint_trig.%s[%d];" % (name, node.op, slot[angle.id]))
        names[node.id] = name
    return lines


def _offset(entry, offset):
    """A joint angle array's entry plus a lane's constant offset (none where it is 0)."""
    return entry if offset == 0.0 else "%s %s %s" % (entry, *_signed(offset))


def _signed(offset):
    """(operator, constant) adding the offset: − for a negative one, as _signed_operands writes it."""
    return ("-" if offset < 0.0 else "+"), format_constant(abs(offset))


# Fewest angles of a limb pair's run read as two interleaved runs (store_interleaved_pairs): four
# fill a vector of each limb's.
PAIR_RUN_MIN = 4


def _pair_runs(pairs):
    """[(slot, count, (source a, source b))] for each run of at least PAIR_RUN_MIN consecutive pair
    angles (slots two apart) whose two limbs' angles are consecutive entries of one array each (a
    pair's joints in q): joint_angle[slot + 2j] = a[j], [slot + 2j + 1] = b[j]. Read entry by entry,
    clang 14 gathered them (four or five gathers in each of humanoid32's and TALOS's functions),
    slow on AMD cores."""
    runs = []
    for start, (a, b) in pairs:
        if runs:
            first_start, count, (a0, b0) = runs[-1]
            if (start == first_start + 2 * count and a == (a0[0], a0[1] + count)
                    and b == (b0[0], b0[1] + count)):
                runs[-1] = (first_start, count + 1, (a0, b0))
                continue
        runs.append((start, 1, (a, b)))
    return [run for run in runs if run[1] >= PAIR_RUN_MIN]


def _transposition(items):
    """(array, base) when lane value J of `items` (per item its four (array, index) sources) is entry J
    of four consecutive runs of len(items) entries, array[base + k·N + J] in lane k: a limb-major
    block that transposed_lanes loads as whole vectors (a strided load became a gather), else None."""
    n = len(items)
    array, base = items[0][0]
    if all(items[j][k] == (array, base + k * n + j) for j in range(n) for k in range(ex.LANES)):
        return array, base
    return None


def _lane_inputs(items):
    """The initialisers of a lane input array: transposed_lanes of a limb-major block, else make_lanes."""
    block = _transposition(items) if all(len(sources) == ex.LANES for sources in items) else None
    if block:
        return ["transposed_lanes<%d, %d>(%s + %d)" % (len(items), j, block[0], block[1]) for j in range(len(items))]
    return ["make_lanes(%s)" % ", ".join("%s[%d]" % s for s in sources) for sources in items]


def _lane_block(fn, order, names):
    """A lane function's lane type, its lane inputs (those used other than by joint sin/cos) and the
    lane constants it uses, each a lane_x[…] array of make_lanes(lane 0, …, lane 3); the used lane
    constants are numbered afresh (`names`)."""
    lanes = fn.lanes
    # lane symbols read by the statements (a lane angle's sin/cos read its lanes from joint_trig)
    symbols = {a.id: a for n in order if not _is_joint_trig(n) for a in n.args if a.op == "sym" and a.lane}
    used = {n.value[0] for n in symbols.values()} - {ex.LANE_CONSTANTS}
    constants = sorted((n for n in symbols.values() if n.value[0] == ex.LANE_CONSTANTS),
                       key=lambda n: n.value[1])
    for k, node in enumerate(constants):
        names[node.id] = "%s[%d]" % (ex.LANE_CONSTANTS, k)
    lines = ["// the isomorphic limbs, one per lane; %s: constants that differ between them"
             % ex.LANE_CONSTANTS, "using Lane = Lanes<Scalar>;"]
    arrays = [(name, _lane_inputs(lanes.inputs[name])) for name in sorted(used)]
    arrays.append((ex.LANE_CONSTANTS, ["make_lanes(%s)" % ", ".join(format_constant(v) for v in
                                                                   lanes.constants[n.value[1]])
                                       for n in constants]))
    for name, items in arrays:
        if items:
            lines.append("Lane %s[%d] = {%s};" % (name, len(items), ",\n    ".join(items)))
    return lines


def _marker(label):
    return "// " + " ".join(label.split())  # one line, whatever the robot's names hold


def emit_body(fn, angle_names=None):
    """C++ statements (list of str, no indentation) computing every output of `fn`; `angle_names`
    maps an input symbol such as ("q", 7) to the identifier its sin/cos are named by."""
    trig, temps, uses = schedule(fn)
    names = {}
    lines = []

    def text(node, nested):
        if node.id in names:
            return names[node.id]
        if node.op == "const":
            return format_constant(node.value)
        if node.op == "sym":
            return "%s[%d]" % node.value
        if node.op == "lane_get":
            return "%s[%d]" % (text(node.args[0], True), node.value)
        if node.op == "lane_rotate":
            return "rotate_lanes<%d>(%s)" % (node.value, text(node.args[0], False))
        if node.op == "neg":
            body = "-" + text(node.args[0], True)
        elif node.op in ("add", "sub"):
            x, symbol, y = _signed_operands(node)
            right = format_constant(y) if isinstance(y, float) else text(y, True)
            body = "%s %s %s" % (text(x, True), symbol, right)
        elif node.op in _BINARY_SYMBOL:
            body = "%s %s %s" % (text(node.args[0], True), _BINARY_SYMBOL[node.op],
                                 text(node.args[1], True))
        else:
            return "%s(%s)" % (node.op, text(node.args[0], False))
        return "(%s)" % body if nested else body

    angle_names = dict(angle_names or {})
    cleared = _zero_filled(fn)
    lines += ["%s[%d] = Scalar(0);" % (name, start) if end == start + 1 else
              "for (int k = %d; k < %d; ++k) %s[k] = Scalar(0);" % (start, end, name)
              for name, runs in cleared.items() for start, end in runs]
    if fn.lanes is not None:
        lines += _lane_block(fn, ex.reachable(fn.output_exprs()), names)
        angle_names.update(fn.lanes.angle_names)
    lines += _trig_block(trig, names, text, angle_names, fn.lanes)
    label = None
    index = 0
    items = _early_stores(fn, temps, cleared)
    tail = len(items)  # the trailing run of output stores gets the "// outputs" marker
    while tail > 0 and isinstance(items[tail - 1], list):
        tail -= 1
    for position, item in enumerate(items):
        if position == tail:
            lines.append("// outputs")
        if isinstance(item, TransposedStore):
            values = ", ".join(ZERO_LANES if v.is_const(0.0) else text(v, False) for v in item.values)
            if item.interleaved():
                lines.append("store_interleaved_lanes<%d>(%s + %d, {%s});" % (
                    len(item.values), item.arg_name, item.starts[0], values))
            else:
                lines.append("store_transposed_lanes<%d>({%s}, {%s});" % (
                    len(item.values), ", ".join("%s + %d" % (item.arg_name, s) for s in item.starts),
                    values))
            continue
        if isinstance(item, list):  # output entries, stored as soon as their values are computed
            arg_name, k, node = item[0]
            if len(item) == 1:
                lines.append("%s[%d] = %s;" % (arg_name, k, text(node, False)))
            elif _whole_lane_value(item):
                lines.append("store_lanes(%s + %d, %s);" % (arg_name, k, text(node.args[0], False)))
            else:
                lines.append("store_lanes(%s + %d, make_lanes(%s));"
                             % (arg_name, k, ", ".join(text(e[2], False) for e in item)))
            continue
        node = item
        if node.label is not None and node.label != label:
            label = node.label
            lines.append(_marker(label))
        name = "t%d" % index
        index += 1
        lines.append("%s %s = %s;" % ("Lane" if node.lane else "Scalar", name, text(node, False)))
        names[node.id] = name
    return lines


# A lane value of zeros in an interleaved run (_zero_padded).
ZERO_LANES = "make_lanes(Scalar(0), Scalar(0), Scalar(0), Scalar(0))"


def _whole_lane_value(entries):
    """Whether a vector store's entries are lanes 0, 1, … of one lane value, in order: then it stores
    that value itself."""
    nodes = [node for _, _, node in entries]
    return (all(n.op == "lane_get" and n.args[0] is nodes[0].args[0] for n in nodes)
            and [n.value for n in nodes] == list(range(len(nodes))))


# An output with at least this many zero entries is cleared by loops first and its zeros not stored
# one by one: a 100-body chain's looped ∂q̈ wrote 30 000 zeros of its right-hand sides as statements.
ZERO_FILL_MIN = 1024
# Up to this many runs of zeros, each is cleared by its own loop and the entries stored are not
# cleared first; beyond, one loop clears the whole output (a loop per run would be code of its own).
# Clearing Talos's M whole, then storing its 1 300 non-zero entries, cost 16 % of its time in memset.
ZERO_RUNS_MAX = 256


def _zero_filled(fn):
    """{output name: [(start, end)]} of the outputs cleared by loops (ZERO_FILL_MIN), the ranges
    those loops clear: the runs of entries not stored (zeros, and those the looped parts write), or
    the whole output (ZERO_RUNS_MAX); never the entries no loop reads (_unread)."""
    cleared = {}
    for arg in fn.traced_arguments():
        values = fn.values[arg.name]
        if sum(1 for node in values if node is not None and node.is_const(0.0)) < ZERO_FILL_MIN:
            continue
        unread = set(_unread(fn, arg.name))
        runs = []
        for k, node in enumerate(values):
            if k in unread:
                continue
            if node is None or node.is_const(0.0):
                if runs and runs[-1][1] == k:
                    runs[-1][1] = k + 1
                else:
                    runs.append([k, k + 1])
        cleared[arg.name] = [tuple(run) for run in runs] if len(runs) <= ZERO_RUNS_MAX else [(0, len(values))]
    return cleared


def _unread(fn, name):
    """The entries of `fn`'s output `name` that the loops after it never read (Function.unread):
    neither stored nor cleared."""
    return dict(fn.unread).get(name, ())


class TransposedStore(list):
    """A store unit of a lane function (its entries, as the other units): K lane values written limb
    by limb, limb l's lanes at starts[l], starts[l] + 1, … (store_transposed_lanes)."""

    def __init__(self, arg_name, starts, values, entries):
        super().__init__(entries)
        self.arg_name, self.starts, self.values = arg_name, starts, values

    def interleaved(self):
        """Whether the limbs' runs follow one another (a trunk dof's column of M at the legs' rows):
        then one run of K·4 entries, stored by store_interleaved_lanes."""
        return all(b - a == len(self.values) for a, b in zip(self.starts, self.starts[1:]))


# A run of fewer lane values stays in the 4-wide stores: two transposed cost about what they save.
TRANSPOSED_MIN = 3
# Fewest lane values of an interleaved run padded with zeros (_zero_padded).
INTERLEAVED_MIN = 2
# Candidate places per lane of a lane value stored more than once (M's symmetric entries): the first few.
TRANSPOSED_PLACES = 3


def _transposed_stores(arg_name, values):
    """The runs of an output where limb l's entries starts[l] + k are lane l of lane values x_0 … x_K−1
    (a leg's column of M: its rows at the trunk's dofs), longest first, each at least TRANSPOSED_MIN
    long and disjoint from the others."""
    places = {}  # (lane value id, lane) -> the entries holding it
    for k, node in enumerate(values):
        if node is not None and node.op == "lane_get":
            places.setdefault((node.args[0].id, node.value), []).append(k)

    def lane_of(k):
        node = values[k] if 0 <= k < len(values) else None
        return (node.args[0], node.value) if node is not None and node.op == "lane_get" else (None, None)

    candidates = []
    for k in range(len(values)):
        value, lane = lane_of(k)
        if value is None or lane != 0:
            continue
        others = [places.get((value.id, l), [])[:TRANSPOSED_PLACES] for l in range(1, ex.LANES)]
        for starts in itertools.product([k], *others):
            run = []
            while True:
                step = [lane_of(s + len(run)) for s in starts]
                if not all(v is not None and v is step[0][0] and l == i for i, (v, l) in enumerate(step)):
                    break
                run.append(step[0][0])
            starts, run = _zero_padded(values, starts, run)
            if len(run) >= TRANSPOSED_MIN and _disjoint(starts, len(run)):
                candidates.append((starts, run))
    chosen, covered = [], set()
    for starts, run in sorted(candidates, key=lambda c: -len(c[1])):
        entries = {s + k for s in starts for k in range(len(run))}
        if not entries & covered:
            covered |= entries
            chosen.append(TransposedStore(arg_name, starts, run,
                                          [(arg_name, e, values[e]) for e in sorted(entries)]))
    return chosen, covered


def _zero_padded(values, starts, run):
    """(starts, run) with the zero entries around each limb's run taken in, as lane values of zeros,
    where that makes the limbs' runs follow one another (a trunk dof's column of M at legs' rows, one
    of the three zero at every leg): one interleaved store then writes them with the rest."""
    stride = starts[1] - starts[0]
    missing = stride - len(run)
    if (len(run) < INTERLEAVED_MIN or missing <= 0
            or any(b - a != stride for a, b in zip(starts, starts[1:]))):
        return starts, run

    def zero(k):
        return 0 <= k < len(values) and values[k] is not None and values[k].is_const(0.0)

    lead = 0
    while lead < missing and all(zero(s - lead - 1) for s in starts):
        lead += 1
    trail = missing - lead
    if not all(zero(s + len(run) + k) for s in starts for k in range(trail)):
        return starts, run
    zeros = values[starts[0] - 1] if lead else values[starts[0] + len(run)]
    return [s - lead for s in starts], [zeros] * lead + run + [zeros] * trail


def _disjoint(starts, length):
    ends = sorted(starts)
    return all(b >= a + length for a, b in zip(ends, ends[1:]))


def _store_units(fn, cleared):
    """The written output entries (argument name, index, node) grouped as they are stored: one by
    one; in a lane function, first the transposed runs (_transposed_stores), then each run of the
    other consecutive written entries of an argument in vector stores of ex.LANES from the run's start
    (the Mini Cheetah's M in lanes: its 324 scalar stores were the bottleneck, 172 -> 110 ns with g++;
    docs/performance.md) where _one_vector says so, the rest one by one. The zeros of the outputs in
    `cleared` (_zero_filled) are not stored: a loop cleared them; nor the entries no loop reads."""
    width = ex.LANES if fn.lanes is not None else 1
    units = []
    for arg in fn.traced_arguments():
        covered = set()
        if fn.lanes is not None:
            transposed, covered = _transposed_stores(arg.name, fn.values[arg.name])
            units += transposed
        unread = set(_unread(fn, arg.name))
        runs = []  # maximal runs of consecutive written entries
        for k, node in enumerate(fn.values[arg.name]):
            if node is None or k in covered or k in unread or (arg.name in cleared and node.is_const(0.0)):
                continue
            if not runs or runs[-1][-1][1] != k - 1:
                runs.append([])
            runs[-1].append((arg.name, k, node))
        for run in runs:
            whole = len(run) - len(run) % width
            for i in range(0, whole, width):
                chunk = run[i:i + width]
                units += [chunk] if _one_vector(chunk) else [[entry] for entry in chunk]
            units += [[entry] for entry in run[whole:]]
    return units


def _one_vector(entries):
    """Whether ex.LANES consecutive entries take one vector store: constants only (one vector
    literal), or lanes of lane values (one value's in order is the value itself; two-source shuffles
    build the rest: lanes 1 and 3 of two values are one unpack). Where a scalar or a constant sits among
    computed values (a leg's entries beside the other legs' zeros, the trunk's block of lane sums),
    each entry is stored on its own: built into a vector, each such entry took about a shuffle, and
    a store is cheaper (the Mini Cheetah's M 4 % faster on Zen 5; docs/performance.md, "Stores
    instead of shuffles"). Splitting the lane mixes too left humanoid32's M 3-4 % slower."""
    return {node.op for _, _, node in entries} in ({"const"}, {"lane_get"})


def _early_stores(fn, temps, cleared):
    """Creation order of the temporaries, each store unit (_store_units) right after the last
    temporary its entries need (the passes stay in order, each marker heads one pass)."""
    place = {n.id: i for i, n in enumerate(temps)}

    def finish(node):  # place of the last temporary an output entry needs (inlined nodes included)
        best, stack, seen = -1, [node], set()
        while stack:
            n = stack.pop()
            if n.id in seen:
                continue
            seen.add(n.id)
            if n.id in place:
                best = max(best, place[n.id])
            else:
                stack.extend(n.args)
        return best

    after = {}
    for unit in _store_units(fn, cleared):
        after.setdefault(max(finish(entry[2]) for entry in unit), []).append(unit)
    items = list(after.get(-1, []))
    for i, n in enumerate(temps):
        items.append(n)
        items += after.get(i, [])
    return items
