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

Usage: tools/instruction_rates.py SUMMARY GENERATED [GHZ [PEAK]] [--paths ROBOT=FLOPS_JSON ...]
  SUMMARY    the peer benchmark's summary.md (rows "| robot | pair | peer min / median | rbdc min /
             median | ratio× |", pairs named "peer_function → rbdc_function")
  GENERATED  the directory holding <robot>/full/*.hpp and <robot>/derivatives/*.hpp
  GHZ        the core's clock (default 3.65: the Zen 4 of 5 December, by a dependent-add loop)
  PEAK       FMAs and additions a cycle, half and half (default 4.05: tools/machine_peak on Zen 5)
  --paths    `rbdc flops ROBOT --scene S --json` outputs, robot by robot (one per scene, any number)
"""
import json
import re
import sys
from pathlib import Path

# quantity: (rbdc function, scene directory, the target ratio)
TARGETS = {"ID": ("inverse_dynamics", "full", 10), "c+g": ("bias", "full", 10),
           "M": ("mass_matrix", "full", 10), "FD": ("forward_dynamics", "full", 10),
           "∂ID": ("inverse_dynamics_derivatives", "derivatives", 8),
           "∂FD": ("forward_dynamics_derivatives", "derivatives", 5)}
FMA_PIPES = 2  # multiplications and FMAs a cycle: both AMD cores measured (tools/machine_peak.cpp)
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


def critical_paths(options):
    """{(robot, function): (cycles, traced part only)} from ROBOT=FLOPS_JSON options."""
    paths = {}
    for option in options:
        robot, _, file = option.partition("=")
        for function, counts in json.loads(Path(file).read_text())["functions"].items():
            path = counts["critical_path"]
            paths.setdefault((robot, function), (path["cycles"], path["traced_part_only"]))
    return paths


def latency_columns(path, peer, ghz):
    """The critical path in ns and the most the peer's time over it allows ('+': a looped form's
    traced part only, so the true bound is tighter)."""
    if path is None:
        return " – | – |"
    cycles, partial = path
    mark = "+" if partial else ""
    return " %.0f%s | %.1f×%s |" % (cycles / ghz, mark, peer / (cycles / ghz), mark)


def main():
    args = sys.argv[1:]
    path_options = args[args.index("--paths") + 1:] if "--paths" in args else []
    args = args[:args.index("--paths")] if "--paths" in args else args
    if len(args) not in (2, 3, 4) or args[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if args and args[0] in ("-h", "--help") else 2
    summary, generated = Path(args[0]), Path(args[1])
    ghz = float(args[2]) if len(args) >= 3 else 3.65
    peak = float(args[3]) if len(args) == 4 else 4.05
    paths = critical_paths(path_options)
    measured = {(m.group(1), m.group(2)): tuple(float(m.group(k).replace(",", "")) for k in (3, 4, 5))
                for m in map(ROW.match, summary.read_text().splitlines()) if m}
    print("| robot | quantity | rbdc ns | instructions | per cycle | ratio | target | per cycle needed "
          "| multiplications | most per cycle |" + (" critical path ns | most by latency |" if paths else ""))
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|" + ("---:|---:|" if paths else ""))
    for robot in dict.fromkeys(robot for robot, _ in measured):
        for quantity, (function, scene, target) in TARGETS.items():
            if (robot, function) not in measured:
                continue
            peer, ours, ratio = measured[(robot, function)]
            header = generated / robot / scene / (function + ".hpp")
            n = instructions(header)
            needed = "met" if ratio >= target else "%.2f" % (n / (peer / target * ghz))
            share = multiplication_share(header)
            most = "%.2f" % min(peak, FMA_PIPES / share) if share else "–"
            print("| %s | %s | %.0f | %d | %.2f | %.2f× | %d× | %s | %s | %s |"
                  % (robot, quantity, ours, n, n / (ours * ghz), ratio, target, needed,
                     "%.0f %%" % (100 * share) if share else "–", most)
                  + (latency_columns(paths.get((robot, function)), peer, ghz) if paths else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
