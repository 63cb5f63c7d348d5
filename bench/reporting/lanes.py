"""The legs in SIMD lanes (issue 11) in bench/report: the Mini Cheetah's lane functions (scene
limb_lanes, bench/lane_cases.cpp) against the scalar generated code and the runtime, in rbdc-bench
runs whose repetitions are randomly interleaved across cases; min and median over every repetition
of every run, and the section of latest.md with the issue's goals."""
import datetime
import json
import os
import statistics

from .common import QUANTITY_TITLES, format_ns, ratio, say
from .runner import run_bench

LANE_QUANTITIES = ["bias", "inverse_dynamics", "mass_matrix", "mass_matrix_lower", "forward_dynamics",
                   "osc_open_chain", "inverse_dynamics_derivatives", "forward_dynamics_derivatives"]
LANE_IMPLEMENTATIONS = ["generated_double_lanes", "generated_double", "generated_float_lanes",
                        "generated_float", "runtime"]
# Issue 11's goals at the minimum of interleaved repetitions (ns), Mini Cheetah; for the derivatives
# issue 12's absolute figures ("about 1 µs", "about 3 µs"; their ratio targets are in the derivatives
# section). The derivative cases exist only in a build with RBDC_BENCH_DERIVATIVES. M's lower
# triangle is held to the stretch (≤ 90 ns): it is Pinocchio's convention (one triangle) that the
# issue's peer timing used. The open-chain OSC recursion has no goal of its own.
GOALS_NS = {"bias": 170, "inverse_dynamics": 190, "mass_matrix": 145, "mass_matrix_lower": 90,
            "forward_dynamics": 630,
            "inverse_dynamics_derivatives": 1000, "forward_dynamics_derivatives": 3000}
TITLES = dict(QUANTITY_TITLES, inverse_dynamics_derivatives="∂τ/∂q, ∂τ/∂v",
              forward_dynamics_derivatives="∂a/∂q, ∂a/∂v, ∂a/∂τ, ∂a/∂f")


def lane_results(build_dir, args):
    """Runs the lane cases `args.lane_runs` times; returns {quantity: {implementation: {"min_ns",
    "median_ns"}}} over all repetitions, with the runs' count, repetitions and load average."""
    pattern = (f"^mini_cheetah/({'|'.join(LANE_QUANTITIES)})/({'|'.join(LANE_IMPLEMENTATIONS)})$")
    samples = {}
    for run in range(args.lane_runs):
        say(f"lanes: run {run + 1} of {args.lane_runs}")
        run_bench(build_dir, args.lane_repetitions, args.min_time, pattern, interleave=True)
        for row in json.loads((build_dir / "rbdc-bench.json").read_text())["benchmarks"]:
            if row.get("run_type") == "iteration":
                samples.setdefault(row["run_name"], []).append(row["cpu_time"])
    table = {}
    for name, times in samples.items():
        _, quantity, implementation = name.split("/")
        table.setdefault(quantity, {})[implementation] = {"min_ns": round(min(times), 2),
                                                          "median_ns": round(statistics.median(times), 2)}
    return {"robot": "mini_cheetah", "runs": args.lane_runs, "repetitions": args.lane_repetitions,
            "load_average": [round(x, 2) for x in os.getloadavg()],
            "date": datetime.date.today().isoformat(), "results": table}


def lane_markdown(lanes):
    """The 'Legs in SIMD lanes' section of latest.md (nothing when no lane run is recorded)."""
    if not lanes:
        return []
    lines = [f"## Legs in SIMD lanes, {lanes['robot']} (issue 11; rbdc-bench on {lanes['date']}, "
             f"{lanes['runs']} runs × {lanes['repetitions']} repetitions randomly interleaved across cases, "
             f"load average {', '.join(f'{x:.1f}' for x in lanes['load_average'])})", "",
             "One state per call, each leg in one lane of a 4-wide vector (scene limb_lanes, "
             "docs/performance.md). Min / median over every repetition of every run.", "",
             "| quantity | lanes double | scalar double | lanes float | scalar float | runtime | "
             "lanes vs scalar (min, median) | lanes vs runtime (median) | goal (min) | met | "
             "lanes median / min (goal ≤ 1.3) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for quantity in LANE_QUANTITIES:
        row = lanes["results"].get(quantity)
        if not row:
            continue
        cell = {i: row.get(i, {}) for i in LANE_IMPLEMENTATIONS}
        pair = {i: f"{format_ns(c.get('min_ns'))} / {format_ns(c.get('median_ns'))}" for i, c in cell.items()}
        lane, scalar, runtime = cell["generated_double_lanes"], cell["generated_double"], cell["runtime"]
        goal = GOALS_NS.get(quantity)
        met = "–" if goal is None else "yes" if lane.get("min_ns") and lane["min_ns"] <= goal else "**no**"
        spread = lane["median_ns"] / lane["min_ns"] if lane.get("min_ns") and lane.get("median_ns") else None
        spread_text = "–" if spread is None else f"{spread:.2f}" + ("" if spread <= 1.3 else " (**no**)")
        lines.append(f"| {TITLES[quantity]} | " + " | ".join(pair[i] for i in LANE_IMPLEMENTATIONS)
                     + f" | {ratio(scalar.get('min_ns'), lane.get('min_ns'))}, "
                       f"{ratio(scalar.get('median_ns'), lane.get('median_ns'))}"
                     + f" | {ratio(runtime.get('median_ns'), lane.get('median_ns'))} | "
                       f"{'–' if goal is None else f'≤ {goal} ns'} | {met} "
                       f"| {spread_text} |")
    return lines + [""]
