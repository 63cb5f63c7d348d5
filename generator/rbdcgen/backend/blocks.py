"""Long bodies as a run of blocks: how a function too long for straight-line code is emitted
(docs/performance.md, "Blocks for long functions" and "Smaller blocks").

g++'s register allocation and scheduling take time that grows faster than linearly with the length
of one function (the 32-DoF humanoid's ∂q̈: 24 800 lines, over 15 minutes at -O3). A body longer
than SPLIT_ABOVE statements is cut into blocks of at most MAX_STATEMENTS, each a separate non-inlined
function with the function's own parameters plus a scratch array; the function calls them in order.
A value defined in one block and used in a later one passes through a scratch slot, stored once
after its definition and loaded once at the top of each block that reads it; a slot is reused once
its last reader has run. Compile time then grows with the number of blocks; the statements and
their order are the same."""

from __future__ import annotations

import heapq
import re
from dataclasses import dataclass

# Bodies up to SPLIT_ABOVE statements stay one function (the Mini Cheetah's ∂q̈ scalar, 6 000
# statements, compiles in seconds; blocks would only add scratch traffic, and clang 14 ran
# humanoid32's OSC recursions 22-28 % slower in blocks); longer ones are cut into blocks of
# MAX_STATEMENTS. g++ 12's time per statement still grows with the block: humanoid32's ∂q̈ (14 672
# statements), g++ -O3 -march=native, user s with another compile on the second core: blocks of
# 1500 40.6 s, 500 28.5 s, 250 16.9 s, 120 19.5 s (docs/performance.md, "Smaller blocks"); run
# time unchanged (g++ 24.0 → 23.1 µs, clang 20.4 → 19.8 µs).
SPLIT_ABOVE = 6500
MAX_STATEMENTS = 250
SCRATCH = "rbdc_scratch"
_DEFINITION = re.compile(r"^const (Scalar|auto) (\w+)(\[\d+\])? = ")
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
    first = _after_joint_trig(body)
    cuts = [0] + list(range(max(first, max_statements), len(body), max_statements)) + [len(body)]
    cuts = sorted(set(cuts))
    block_of = {}
    for b in range(len(cuts) - 1):
        for i in range(cuts[b], cuts[b + 1]):
            block_of[i] = b
    defined = {}  # scalar name -> (block, statement index)
    for i, statement in enumerate(body):
        match = _DEFINITION.match(statement)
        if match and match.group(1) == "Scalar" and not match.group(3):
            defined[match.group(2)] = block_of[i]
    readers = {}  # name defined in an earlier block -> blocks reading it
    for i, statement in enumerate(body):
        for name in _references(statement):
            if name in defined and defined[name] != block_of[i]:
                readers.setdefault(name, set()).add(block_of[i])
    slots, size = _allocate(readers, defined)
    parts = []
    for b in range(len(cuts) - 1):
        statements = body[cuts[b]:cuts[b + 1]]
        loads = ["const Scalar %s = %s[%d];" % (name, SCRATCH, slots[name])
                 for name in sorted(readers, key=lambda n: slots[n]) if b in readers[name]]
        stored = []
        for statement in statements:
            stored.append(statement)
            match = _DEFINITION.match(statement)
            if match and match.group(2) in readers:
                stored.append("%s[%d] = %s;" % (SCRATCH, slots[match.group(2)], match.group(2)))
        used = set().union(*(_references(s) for s in loads + stored))
        unused = ["static_cast<void>(%s);" % p for p in [*parameters, SCRATCH] if p not in used]
        parts.append(unused + loads + stored)
    arguments = ", ".join(list(parameters) + [SCRATCH])
    main = ["Scalar %s[%d];" % (SCRATCH, max(size, 1))]
    main += ["%s_part%d(%s);" % (function_name, b, arguments) for b in range(len(parts))]
    return Blocks(parts=parts, main=main, scratch_size=size)


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
    for name in sorted(readers, key=lambda n: (defined[n], n)):
        start = defined[name]
        while busy and busy[0][0] < start:
            heapq.heappush(free, heapq.heappop(busy)[1])
        if free:
            slot = heapq.heappop(free)
        else:
            slot, size = size, size + 1
        slots[name] = slot
        heapq.heappush(busy, (max(readers[name]), slot))
    return slots, size
