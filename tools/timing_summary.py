#!/usr/bin/python3
"""Summarises a short rbdc-bench run (Google Benchmark JSON on stdin, cases "robot/quantity/impl"):
per quantity the minimum and median CPU time of the generated code and of the runtime over the
repetitions, and how many times faster the generated code is. One run on a shared machine: the
ratio is the figure to read, not the absolute times (docs/benchmarks.md has the full method).

Usage: rbdc-bench --benchmark_format=json ... | tools/timing_summary.py
"""
import json
import statistics
import sys


def main():
    if len(sys.argv) > 1:
        print(__doc__.strip())
        return 0 if sys.argv[1] in ("-h", "--help") else 2
    runs = [b for b in json.load(sys.stdin)["benchmarks"] if b.get("run_type") == "iteration"]
    times = {}
    for b in runs:
        robot, quantity, implementation = b["run_name"].split("/")[:3]
        scale = {"ns": 1, "us": 1e3, "ms": 1e6}[b["time_unit"]]
        times.setdefault((robot, quantity), {}).setdefault(implementation, []).append(b["cpu_time"] * scale)
    print(f"{'robot/quantity':<34}{'generated ns (min/median)':>28}{'runtime ns (min/median)':>26}{'speed-up':>10}")
    for (robot, quantity), by_impl in times.items():
        gen, run = by_impl.get("generated_double"), by_impl.get("runtime")
        if not gen or not run:
            continue
        print(f"{robot + '/' + quantity:<34}{min(gen):>14.0f} / {statistics.median(gen):<11.0f}"
              f"{min(run):>12.0f} / {statistics.median(run):<11.0f}{min(run) / min(gen):>9.1f}×")
    return 0


if __name__ == "__main__":
    sys.exit(main())
