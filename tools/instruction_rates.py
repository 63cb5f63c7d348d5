#!/usr/bin/python3
"""What rate issue 20's targets would ask of the machine: per robot and quantity, the generated
function's arithmetic instructions (its header's `/// schedule:` count, else its operation count),
its measured median time, the instructions it retires per cycle, and the rate the target ratio over
the peer would need at the same instruction count. Then the most the core could sustain for that
code: its multiplications (the operation table's share of its multiplications and additions) go
to the two FMA pipes, so at most 2 / share instructions a cycle, and never more than the mixed
peak (tools/machine_peak.cpp). A needed rate above that means the gap closes only with
fewer instructions, not with better scheduling (docs/performance.md, "What bounds each remaining gap").
With --paths, also the latency side: the function's critical path (`rbdc flops --json`, graph/latency.py)
in ns and the most the peer's time over it allows; a path longer than the target's time means no
schedule of the same operations reaches the target (docs/performance.md, "The critical path").
With --code, also the front end's side: the bytes of the function's straight-line code in the
harness's binary, and the most the peer's time over their streaming through the decoders would
allow: a bound for the functions whose code streams, which tools/code_fetch_test.py shows
(docs/performance.md, "Code that streams").

Usage: tools/instruction_rates.py SUMMARY GENERATED [GHZ [PEAK]] [--paths ROBOT=FLOPS_JSON ...]
                                  [--code ROBOT=BINARY ...]
  SUMMARY    the peer benchmark's summary.md (rows "| robot | pair | peer min / median | rbdc min /
             median | ratio× |", pairs named "peer_function → rbdc_function")
  GENERATED  the directory holding <robot>/full/*.hpp and <robot>/derivatives/*.hpp
  GHZ        the core's clock (default 3.65: the Zen 4 of 5 December, by a dependent-add loop)
  PEAK       FMAs and additions a cycle, half and half (default 4.05: tools/machine_peak on Zen 5)
  --paths    `rbdc flops ROBOT --scene S --json` outputs, robot by robot (one per scene, any number)
  --code     the harness's benchmark binaries, robot by robot (read with `nm`)
"""
import json
import re
import subprocess
import sys
from pathlib import Path

# quantity: (rbdc function, scene directory, the target ratio)
TARGETS = {"ID": ("inverse_dynamics", "full", 10), "c+g": ("bias", "full", 10),
           "M": ("mass_matrix", "full", 10), "FD": ("forward_dynamics", "full", 10),
           "∂ID": ("inverse_dynamics_derivatives", "derivatives", 8),
           "∂FD": ("forward_dynamics_derivatives", "derivatives", 5)}
FMA_PIPES = 2  # multiplications and FMAs a cycle: both AMD cores measured (tools/machine_peak.cpp)
MIXED_PEAK = 4.05  # FMAs and additions a cycle, half and half: tools/machine_peak on Zen 5
STREAMED_BYTES_PER_NS = 64  # straight-line code through the decoders: tools/machine_peak on Zen 5
# numbers with thousands separators, the ratio bold where the harness's summary marks it
ROW = re.compile(r"\| (\S+) \| \S+ → (\w+) \| [\d.,]+ / ([\d.,]+) \| [\d.,]+ / ([\d.,]+) \| \**([\d.]+)×")


def doc_comment(header):
    """The header's /// lines as one line of single-spaced words (tables and wrapped lines read alike)."""
    return " ".join(" ".join(line.lstrip("/").split()) for line in header.read_text().splitlines()
                    if line.startswith("///"))


def instructions(header):
    """The schedule line's arithmetic instructions, else the operation table's total."""
    doc = doc_comment(header)
    counted = re.search(r"schedule: .*?: (\d+) arithmetic instructions", doc)
    if counted:
        return int(counted.group(1))
    return int(re.search(r"operations mul add div sqrt trig neg total (?:\d+ ){6}(\d+)", doc).group(1))


def multiplication_share(header):
    """Multiplications over multiplications and additions in the operation table (the counted
    instructions count an FMA as a multiplication and an addition), or None without a table."""
    doc = doc_comment(header)
    table = re.search(r"operations mul add div sqrt trig neg total (\d+) (\d+) ", doc)
    return int(table.group(1)) / (int(table.group(1)) + int(table.group(2))) if table else None


def most_per_cycle(share, peak):
    """The most instructions a cycle the core sustains for code whose multiplications are `share` of
    its instructions: the two FMA pipes take the multiplications, and never above the mixed peak."""
    return min(peak, FMA_PIPES / share) if share else peak


def critical_paths(options):
    """{(robot, function): (cycles, traced part only)} from ROBOT=FLOPS_JSON options."""
    paths = {}
    for option in options:
        robot, _, file = option.partition("=")
        for function, counts in json.loads(Path(file).read_text())["functions"].items():
            path = counts["critical_path"]
            paths.setdefault((robot, function), (path["cycles"], path["traced_part_only"]))
    return paths


def code_sizes(options):
    """{robot: {namespace: bytes}} from ROBOT=BINARY options: each generated function's namespace
    (rbdc_gen::ROBOT::common::FUNCTION_HASH) and the bytes of the functions defined in it, which are
    its straight-line code (the loops it calls are shared templates outside it)."""
    sizes = {}
    for option in options:
        robot, _, binary = option.partition("=")
        listing = subprocess.run(["nm", "-S", "-C", binary], capture_output=True, text=True, check=True).stdout
        for line in listing.splitlines():
            fields = line.split(maxsplit=3)  # address, size, type, name; code is of type t, T, w or W
            code = len(fields) == 4 and fields[2] in "tTwW"
            namespace = re.match(r"(?:void )?(rbdc_gen::\w+::common::\w+)::", fields[3]) if code else None
            if namespace:
                sizes.setdefault(robot, {}).setdefault(namespace.group(1), 0)
                sizes[robot][namespace.group(1)] += int(fields[1], 16)
    return sizes


def code_namespace(header):
    """The namespace of the code a generated function's header includes (rbdc_gen::ROBOT::common::
    FUNCTION_HASH), or None for a header without one."""
    included = re.search(r'#include "(\w+)/common/(\w+)\.hpp"', header.read_text())
    return "rbdc_gen::%s::common::%s" % included.groups() if included else None


def code_columns(header, robot, sizes, peer):
    """The function's straight-line KB, and the most the peer's time over its streaming would allow
    ('–' without the binary)."""
    size = sizes.get(robot, {}).get(code_namespace(header))
    if size is None:
        return " – | – |"
    streamed = size / STREAMED_BYTES_PER_NS
    return " %.1f | %.1f× |" % (size / 1024, peer / streamed)


def latency_columns(path, peer, ghz):
    """The critical path in ns and the most the peer's time over it allows ('+': a looped form's
    traced part only, so the true bound is tighter)."""
    if path is None:
        return " – | – |"
    cycles, partial = path
    mark = "+" if partial else ""
    return " %.0f%s | %.1f×%s |" % (cycles / ghz, mark, peer / (cycles / ghz), mark)


def main():
    args, options, flag = [], {"--paths": [], "--code": []}, None
    for arg in sys.argv[1:]:
        if arg in options:
            flag = arg
        else:
            (options[flag] if flag else args).append(arg)
    if len(args) not in (2, 3, 4) or args[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if args and args[0] in ("-h", "--help") else 2
    summary, generated = Path(args[0]), Path(args[1])
    ghz = float(args[2]) if len(args) >= 3 else 3.65
    peak = float(args[3]) if len(args) == 4 else MIXED_PEAK
    paths, sizes = critical_paths(options["--paths"]), code_sizes(options["--code"])
    measured = {(m.group(1), m.group(2)): tuple(float(m.group(k).replace(",", "")) for k in (3, 4, 5))
                for m in map(ROW.match, summary.read_text().splitlines()) if m}
    print("| robot | quantity | rbdc ns | instructions | per cycle | ratio | target | per cycle needed "
          "| multiplications | most per cycle |" + (" critical path ns | most by latency |" if paths else "")
          + (" code KB | most if it streams |" if sizes else ""))
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|" + ("---:|---:|" if paths else "")
          + ("---:|---:|" if sizes else ""))
    for robot in dict.fromkeys(robot for robot, _ in measured):
        for quantity, (function, scene, target) in TARGETS.items():
            if (robot, function) not in measured:
                continue
            peer, ours, ratio = measured[(robot, function)]
            header = generated / robot / scene / (function + ".hpp")
            n = instructions(header)
            needed = "met" if ratio >= target else "%.2f" % (n / (peer / target * ghz))
            share = multiplication_share(header)
            most = "%.2f" % most_per_cycle(share, peak) if share else "–"
            print("| %s | %s | %.0f | %d | %.2f | %.2f× | %d× | %s | %s | %s |"
                  % (robot, quantity, ours, n, n / (ours * ghz), ratio, target, needed,
                     "%.0f %%" % (100 * share) if share else "–", most)
                  + (latency_columns(paths.get((robot, function)), peer, ghz) if paths else "")
                  + (code_columns(header, robot, sizes, peer) if sizes else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
