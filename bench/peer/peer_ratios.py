#!/usr/bin/env python3
"""Pinocchio against rbdc's generated code from generated_vs_pinocchio's Google Benchmark JSON files.

Prints one Markdown table per robot (the JSON's context "robot"): for each quantity, the median CPU
time per call of Pinocchio and of rbdc, the ratio of the medians and the ratio of the minimums, all
taken over every repetition of every run given (the aggregates the files also hold are ignored). With
--before, the same ratios from another set of runs (e.g. before a change) in one more column.

Example: bench/peer/peer_ratios.py OUT/mini_cheetah/run*.json --before OLD/mini_cheetah/run*.json
"""
import argparse
import json
import statistics
import sys
from collections import defaultdict

# quantity → (Pinocchio's function, rbdc's), in the order of the table
PAIRS = {
    "ID": ("rnea", "inverse_dynamics"),
    "c+g": ("nonLinearEffects", "bias"),
    "g": ("computeGeneralizedGravity", "gravity_terms"),
    "M": ("crba", "mass_matrix"),
    "FD": ("aba", "forward_dynamics"),
    "dID": ("computeRNEADerivatives", "inverse_dynamics_derivatives"),
    "dFD": ("computeABADerivatives", "forward_dynamics_derivatives"),
}
NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def read(paths):
    """{robot: {"pin/ID": [cpu ns of each repetition], ...}} from the runs' files."""
    times = defaultdict(lambda: defaultdict(list))
    for path in paths:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        robot = data.get("context", {}).get("robot", path)
        for b in data["benchmarks"]:
            if b.get("run_type", "iteration") == "iteration":
                times[robot][b.get("run_name", b["name"])].append(b["cpu_time"] * NS[b.get("time_unit", "ns")])
    return times


def ratios(runs, quantity):
    """(Pinocchio median, rbdc median, ratio of medians, ratio of minimums, repetitions), or None."""
    pin, gen = runs.get("pin/" + quantity), runs.get("rbdc/" + quantity)
    if not pin or not gen:
        return None
    p, r = statistics.median(pin), statistics.median(gen)
    return p, r, p / r, min(pin) / min(gen), f"{len(pin)} / {len(gen)}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", metavar="RUN.json", help="--benchmark_out files of one set of runs")
    parser.add_argument("--before", nargs="+", metavar="RUN.json", default=[],
                        help="files of an earlier set of runs, shown as its ratios")
    args = parser.parse_args()
    now, before = read(args.runs), read(args.before)
    for robot, runs in now.items():
        print(f"\n{robot}: CPU time per call, median over {len(args.runs)} run(s) x their repetitions\n")
        header = "| quantity | Pinocchio → rbdc | Pinocchio ns | rbdc ns | ratio of medians | ratio of mins | n |"
        rule = "|---|---|---|---|---|---|---|"
        if before:
            header += " before: medians / mins |"
            rule += "---|"
        print(header + "\n" + rule)
        for quantity, (pin_name, rbdc_name) in PAIRS.items():
            r = ratios(runs, quantity)
            if r is None:
                continue
            row = (f"| {quantity} | {pin_name} → {rbdc_name} | {r[0]:,.1f} | {r[1]:,.1f} | **{r[2]:.2f}×** "
                   f"| {r[3]:.2f}× | {r[4]} |")
            if before:
                b = ratios(before.get(robot, {}), quantity)
                row += f" {b[2]:.2f}× / {b[3]:.2f}× |" if b else " – |"
            print(row)
    return 0 if now else 1


if __name__ == "__main__":
    sys.exit(main())
