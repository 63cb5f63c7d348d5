"""The derivatives (issue 12) in bench/report: timings of rbdc-bench-derivatives merged into the
results table (each derivative case also per call of its primal function from the same run), and the
errors of rbdc-derivative-error-study against the generated derivative code in __float128, with their
sections of latest.md."""
import datetime
import json
import os
import re
import subprocess
import sys

from .common import ROBOTS, format_ns, ratio, say
from .runner import bench_statistics, compiler_version, flop_counts, run_bench

DERIVATIVE_TARGETS = ["rbdc-bench-derivatives", "rbdc-derivative-error-study"]

# Derivatives (issue 12, rbdc-bench-derivatives): the quantities, the implementations in table
# order, and the primal call each is quoted against (timed in the same run).
DERIVATIVE_PRIMAL = {"inverse_dynamics_derivatives": "inverse_dynamics",
                     "forward_dynamics_derivatives": "forward_dynamics"}
# generated_double_xW: Batch<double>, W its lanes on the machine (generated_double_x8 with AVX-512).
DERIVATIVE_IMPLEMENTATIONS = ["generated_double", "generated_float", "generated_double_xW", "runtime",
                              "dual_ad", "finite_differences"]


def _in_table_order(implementations):
    """`implementations` in DERIVATIVE_IMPLEMENTATIONS' order (a batch by its kind), others left out."""
    kinds = {name: re.sub(r"_x\d+$", "_xW", name) for name in implementations}
    return sorted((name for name, kind in kinds.items() if kind in DERIVATIVE_IMPLEMENTATIONS),
                  key=lambda name: DERIVATIVE_IMPLEMENTATIONS.index(kinds[name]))


DERIVATIVE_TITLES = {"inverse_dynamics_derivatives": "∂τ/∂q, ∂τ/∂v",
                     "forward_dynamics_derivatives": "∂a/∂q, ∂a/∂v, ∂a/∂τ, ∂a/∂f"}
# The error study's parts (generated outputs) in table order, and the variants in column order.
PART_TITLES = {"dtau_dq": "∂τ/∂q", "dtau_dv": "∂τ/∂v", "da_dq": "∂a/∂q", "da_dv": "∂a/∂v",
               "da_dtau": "∂a/∂τ", "da_df": "∂a/∂f", "dbias_dq": "∂(c + g)/∂q", "dbias_dv": "∂(c + g)/∂v",
               "dg_dq": "∂g/∂q", "dpdot_dq": "∂(feet velocities)/∂q", "dtau_e_dq": "∂(Jᵀf)/∂q"}
ERROR_VARIANTS = ["generated_double", "generated_float", "runtime", "dual_ad", "finite_differences"]


def run_derivatives(build_dir, args):
    """Times rbdc-bench-derivatives (repetitions randomly interleaved across cases) and returns
    ({case: min ns}, {case: median ns})."""
    minimum = run_bench(build_dir, args.derivative_repetitions, args.min_time, args.filter,
                        "rbdc-bench-derivatives", interleave=True, statistic="min")
    results = json.loads((build_dir / "rbdc-bench-derivatives.json").read_text())
    return minimum, bench_statistics(results, "median")


def merge_derivatives(table, minimum, median, counts, repetitions):
    """Adds the `<quantity>_derivatives` rows to `table` and returns the details: the primal calls of
    the same run and each derivative case's time per primal call (medians, and mins)."""
    primal = {}
    for name, ns in median.items():
        robot, quantity, implementation = name.split("/")
        if quantity not in DERIVATIVE_PRIMAL:
            primal[f"{robot}/{quantity}"] = {"ns": round(ns, 2), "min_ns": round(minimum[name], 2)}
    for name, ns in median.items():
        robot, quantity, implementation = name.split("/")
        if quantity not in DERIVATIVE_PRIMAL:
            continue
        reference = primal.get(f"{robot}/{DERIVATIVE_PRIMAL[quantity]}")
        lanes = re.search(r"_x(\d+)$", implementation)
        kind = "generic" if implementation == "runtime" else "generated"
        flops = counts.get(robot, {}).get(quantity, {}).get(kind) \
            if implementation.startswith("generated") or implementation == "runtime" else None
        entry = {"ns": round(ns, 2), "min_ns": round(minimum[name], 2),
                 "flops": flops * int(lanes.group(1)) if flops and lanes else flops}
        if reference:
            entry["per_primal"] = round(ns / reference["ns"], 2)
            entry["per_primal_min"] = round(minimum[name] / reference["min_ns"], 2)
        table.setdefault(robot, {}).setdefault(quantity, {})[implementation] = entry
    return {"primal": primal, "repetitions": repetitions, "load_average": os.getloadavg(),
            "date": datetime.date.today().isoformat()}


def derivative_markdown(table, details):
    """The derivative section of latest.md (empty without derivative rows)."""
    lines = []
    for robot in ROBOTS:
        rows = {q: table.get(robot, {}).get(q) for q in DERIVATIVE_PRIMAL if table.get(robot, {}).get(q)}
        if not rows:
            continue
        primal = details.get("primal", {})
        lines += [f"## Derivatives, {robot} (issue 12; rbdc-bench-derivatives run on {details.get('date')}, "
                  f"{details.get('repetitions')} repetitions randomly interleaved across cases, load average "
                  f"{', '.join(f'{x:.1f}' for x in details.get('load_average', []))})", ""]
        for quantity, primal_quantity in DERIVATIVE_PRIMAL.items():
            reference = primal.get(f"{robot}/{primal_quantity}")
            if quantity in rows and reference:
                lines.append(f"- one generated {primal_quantity.replace('_', ' ')} call in the same run: "
                             f"min {format_ns(reference['min_ns'])} ns, median {format_ns(reference['ns'])} ns")
        lines += ["", "| quantity | implementation | min ns | median ns | × one primal call (min, median) | "
                  "FLOPs | generated double faster by (median) |", "|---|---|---|---|---|---|---|"]
        for quantity, entries in rows.items():
            fastest = entries.get("generated_double", {}).get("ns")
            for implementation in _in_table_order(entries):
                e = entries[implementation]
                per = (f"{e['per_primal_min']:.1f}×, {e['per_primal']:.1f}×" if "per_primal" in e else "–")
                lanes = re.search(r"_x(\d+)$", implementation)
                note = f" (per state {format_ns(e['ns'] / int(lanes.group(1)))})" if lanes else ""
                faster = ratio(e["ns"], fastest) if implementation != "generated_double" else "–"
                lines.append(f"| {DERIVATIVE_TITLES[quantity]} | {implementation} | {format_ns(e['min_ns'])} | "
                             f"{format_ns(e['ns'])}{note} | {per} | {e.get('flops') or '–'} | {faster} |")
        lines.append("")
    if lines:
        lines += ["Derivative targets (issue 12, Mini Cheetah): ∂τ/∂(q, v) ≤ 4× one inverse dynamics, "
                  "∂a/∂(q, v, τ) ≤ 3× one forward dynamics (here ∂a/∂f is included), generated ≥ 10× "
                  "faster than the runtime and ≥ 20× faster than finite differences. dual_ad runs the "
                  "generated primal code on Dual<12> numbers, 12 directions per call (Mini Cheetah: 3 calls "
                  "for the 36 directions of ∂τ, 5 for the 60 of ∂a); finite_differences calls it 2 × "
                  "(number of directions) times in double. FLOPs of the generated "
                  "code from `rbdc flops --scene scenes/derivatives.yaml`; runtime: its generic count.", ""]
    return lines


def derivative_results(build_dir, compiler, table, args):
    """Runs both derivative programs of build_dir, adds the timings to `table` and returns the details
    (merge_derivatives) with the compiler, the error rows and their number of states."""
    say(f"running rbdc-bench-derivatives ({compiler})")
    minimum, median = run_derivatives(build_dir, args)
    derivatives = merge_derivatives(table, minimum, median, flop_counts(build_dir, "derivatives"),
                                    args.derivative_repetitions)
    derivatives["compiler"] = compiler_version(compiler)
    derivatives["errors"] = run_derivative_errors(build_dir, args.states, table)
    derivatives["error_states"] = args.states
    return derivatives


def run_derivative_errors(build_dir, states, table):
    """Runs rbdc-derivative-error-study and returns its rows, each with the time of the benchmark case
    that runs its variant (None for the quantities rbdc-bench-derivatives does not time)."""
    say(f"running rbdc-derivative-error-study ({states} states)")
    out = build_dir / "derivative_error_study.json"
    with open(out, "w") as stream:
        result = subprocess.run([build_dir / "bin" / "rbdc-derivative-error-study", "--states", str(states)],
                                stdout=stream)
    if result.returncode != 0:
        sys.exit("bench/report: rbdc-derivative-error-study failed")
    rows = []
    for row in json.loads(out.read_text())["rows"]:
        quantity, implementation = row["bench"].split("/")
        ns = table.get(row["robot"], {}).get(quantity, {}).get(implementation, {}).get("ns")
        rows.append(dict(row, ns=ns))
    return rows


def derivative_error_markdown(rows, states):
    """The per-quantity error table of latest.md (empty without rows)."""
    if not rows:
        return []
    lines = [f"## Derivative errors ({states} random states per robot; reference: the generated derivative "
             "code in __float128)", "",
             "Relative error ‖x − x_ref‖₂ / ‖x_ref‖₂ of each output matrix, median / max over the states. "
             "dual_ad: the generated primal code on dual numbers; finite_differences: central, step 1e-6, "
             "of the generated primal code in double. Issue 12's bound: double ≤ 1e-12 (median).", ""]
    for robot in ROBOTS:
        robot_rows = {(r["part"], r["variant"]): r for r in rows if r["robot"] == robot}
        if not robot_rows:
            continue
        lines += [f"### {robot}", "", "| output | " + " | ".join(v.replace("_", " ") for v in ERROR_VARIANTS) + " |",
                  "|---|" + "---|" * len(ERROR_VARIANTS)]
        for part, title in PART_TITLES.items():
            cells = []
            for variant in ERROR_VARIANTS:
                r = robot_rows.get((part, variant))
                cells.append(f"{r['median']:.1e} / {r['max']:.1e}" if r and r["median"] is not None else "–")
            if any(c != "–" for c in cells):
                lines.append(f"| {title} | " + " | ".join(cells) + " |")
        lines.append("")
    return lines
