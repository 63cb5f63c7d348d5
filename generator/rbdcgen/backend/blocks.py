"""Long bodies as a run of blocks: how a function too long for straight-line code is emitted
(docs/performance.md, "Blocks for long functions" and "Smaller blocks").

g++'s register allocation and scheduling take time that grows faster than linearly with the length
of one function (the 32-DoF humanoid's ∂q̈: 24 800 lines, over 15 minutes at -O3). A body longer
than SPLIT_ABOVE statements is cut into blocks of at most MAX_STATEMENTS, each a separate non-inlined
function with the function's own parameters plus a scratch array; the function calls them in order.
A value defined in one block and used in a later one passes through a scratch slot, stored once
after its definition and loaded once at the top of each block that reads it; a slot is reused once
its last reader has run. Compile time then grows with the number of blocks; the statements and
their order are the same. A lane function's lane values pass the same way, ex.LANES slots each
(store_lanes, load_lanes), and its lane inputs and constants (the arrays its body starts with, cheap
to build and folded by the compiler) are declared again in each block that reads them."""

from __future__ import annotations

import heapq
import re
from dataclasses import dataclass

from ..graph import expr as ex

# Bodies up to SPLIT_ABOVE statements stay one function (the Mini Cheetah's ∂q̈ scalar, 6 000
# statements, compiles in seconds; blocks would only add scratch traffic, and clang 14 ran
# humanoid32's OSC recursions 22-28 % slower in blocks); longer ones are cut into blocks of
# MAX_STATEMENTS. g++ 12's time per statement still grows with the block: humanoid32's ∂q̈ (14 672
# statements), g++ -O3 -march=native, user s with another compile on the second core: blocks of
# 1500 40.6 s, 500 28.5 s, 250 16.9 s, 120 19.5 s (docs/performance.md, "Smaller blocks"); run
# time unchanged (g++ 24.0 → 23.1 µs, clang 20.4 → 19.8 µs).
SPLIT_ABOVE = 6500
# Lane code has the same threshold. It had a lower one while g++ kept const lane values in memory
# (backend/emit.py): TALOS's ∂q̈ terms in lanes (5 500 statements) then took 17.7-19.3 s as one
# function and ran in 22 blocks; with the values in registers they take 12.5 s whole (14.4 s in
# blocks) and the ∂q̈ runs 3.5 % faster whole (docs/performance.md, "Lane values g++ can keep in
# registers").
MAX_STATEMENTS = 250
SCRATCH = "rbdc_scratch"
LANE_TYPE = "using Lane = Lanes<Scalar>;"  # a lane function's first statement
_DEFINITION = re.compile(r"^(Scalar|Lane|auto) (\w+)(\[\d+\])? = ")
_IDENTIFIER = re.compile(r"\b[A-Za-z_]\w*\b")


@dataclass(frozen=True)
class Blocks:
    parts: list          # per block: its statements
    main: list           # the function's body: the scratch array and one call per block
    scratch_size: int


def _references(statement):
    return set() if statement.startswith("//") else set(_IDENTIFIER.findall(statement))


def split(body, parameters, function_name, max_statements=MAX_STATEMENTS):
    """`body` (emit_body's statements) as Blocks, or None when it is short enough to stay one
    function. `parameters`: the function's parameter names, in order."""
    if len(body) <= SPLIT_ABOVE:
        return None
    body, repeated = _lane_setup(body)
    first = _after_joint_trig(body)
    cuts = [0] + list(range(max(first, max_statements), len(body), max_statements)) + [len(body)]
    cuts = sorted(set(cuts))
    block_of = {}
    for b in range(len(cuts) - 1):
        for i in range(cuts[b], cuts[b + 1]):
            block_of[i] = b
    defined = {}  # passable name -> (type, block)
    for i, statement in enumerate(body):
        match = _DEFINITION.match(statement)
        if match and match.group(1) != "auto" and not match.group(3):
            defined[match.group(2)] = (match.group(1), block_of[i])
    references = [_references(statement) for statement in body]
    readers = {}  # name defined in an earlier block -> blocks reading it
    for i, statement in enumerate(body):
        for name in references[i]:
            if name in defined and defined[name][1] != block_of[i]:
                readers.setdefault(name, set()).add(block_of[i])
    place, size = _places(readers, defined)
    parts = []
    read_in = [[] for _ in range(len(cuts) - 1)]  # per block, the passed names it reads, by place
    for name in sorted(readers, key=lambda n: place[n]):
        for b in readers[name]:
            read_in[b].append(name)
    for b in range(len(cuts) - 1):
        loads = [_load(name, defined[name][0], place[name]) for name in read_in[b]]
        stored = []
        used = set().union(*(_references(s) for s in loads), *references[cuts[b]:cuts[b + 1]])
        for statement in body[cuts[b]:cuts[b + 1]]:
            stored.append(statement)
            match = _DEFINITION.match(statement)
            if match and match.group(2) in readers:
                stored.append(_store(match.group(2), defined[match.group(2)][0], place[match.group(2)]))
                used.add(SCRATCH)
        setup = ([LANE_TYPE] if repeated else []) + [
            statement for name, statement in repeated if name in used]
        unused = ["static_cast<void>(%s);" % p for p in [*parameters, SCRATCH] if p not in used]
        parts.append(setup + unused + loads + stored)
    arguments = ", ".join(list(parameters) + [SCRATCH])
    main = ["Scalar %s[%d];" % (SCRATCH, max(size, 1))]
    main += ["%s_part%d(%s);" % (function_name, b, arguments) for b in range(len(parts))]
    return Blocks(parts=parts, main=main, scratch_size=size)


def _lane_setup(body):
    """A lane function's body without its setup, and the setup's lane arrays as (name, statement):
    every block that reads one declares it again. A scalar function's body as it is."""
    if LANE_TYPE not in body:
        return body, []
    rest, repeated = [], []
    for statement in body:
        match = _DEFINITION.match(statement)
        if statement == LANE_TYPE:
            continue
        if match and match.group(1) == "Lane" and match.group(3):
            repeated.append((match.group(2), statement))
        else:
            rest.append(statement)
    return rest, repeated


def _places(readers, defined):
    """Each passed value's first scratch entry: scalars one slot each, lane values ex.LANES
    consecutive ones after them; and the scratch's size."""
    scalars, scalar_size = _allocate({n: r for n, r in readers.items() if defined[n][0] == "Scalar"}, defined)
    lanes, lane_size = _allocate({n: r for n, r in readers.items() if defined[n][0] == "Lane"}, defined)
    place = dict(scalars)
    place.update({name: scalar_size + ex.LANES * slot for name, slot in lanes.items()})
    return place, scalar_size + ex.LANES * lane_size


def _load(name, kind, place):
    if kind == "Lane":
        return "Lane %s = load_lanes(%s + %d);" % (name, SCRATCH, place)
    return "Scalar %s = %s[%d];" % (name, SCRATCH, place)


def _store(name, kind, place):
    if kind == "Lane":
        return "store_lanes(%s + %d, %s);" % (SCRATCH, place, name)
    return "%s[%d] = %s;" % (SCRATCH, place, name)


def _after_joint_trig(body):
    """Index after the joint sin/cos block (its array and struct stay in the first block)."""
    last = -1
    for i, statement in enumerate(body):
        if "joint_trig" in statement or "joint_angle" in statement:
            last = i
    return last + 1


def _allocate(readers, defined):
    """Scratch slot per passed value, a slot reused after the last block that reads its value (the
    lowest free slot first; heaps, since a long body passes thousands of values)."""
    free, busy, slots, size = [], [], {}, 0
    for name in sorted(readers, key=lambda n: (defined[n][1], n)):
        start = defined[name][1]
        while busy and busy[0][0] < start:
            heapq.heappush(free, heapq.heappop(busy)[1])
        if free:
            slot = heapq.heappop(free)
        else:
            slot, size = size, size + 1
        slots[name] = slot
        heapq.heappush(busy, (max(readers[name]), slot))
    return slots, size
