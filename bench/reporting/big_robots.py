"""bench/report --big-robots: the robots of bench/big_robots.json (Talos from the robot corpus, a
100-link chain), generated at build time in their own build directory (RBDC_BENCH_BIG_ROBOTS=ON,
cmake/RbdcBigRobots.cmake). Times every quantity rbdc-bench and rbdc-bench-derivatives have for them
(generated code against the runtime and MuJoCo), counts their FLOPs, and measures what each generated
header costs the compiler: g++ -O3 -march=native on a translation unit that instantiates its one
function for double, with wall time and peak memory (issue 20's ≤ 20 s and ≤ 2 GB per header).
Writes results/bench/big_robots.md and big_robots.json."""
import datetime
import json
import os
import pathlib
import re

from result_files import write_result

from .compile_cost import compile_costs, cost_table
from .common import QUANTITY_TITLES, RESULTS, ROOT, format_ns, ratio, say
from .derivatives import DERIVATIVE_TITLES
from .runner import bench_statistics, build, compiler_version, flop_counts, machine_description, run_bench

PROGRAMS = ["rbdc-bench", "rbdc-bench-derivatives"]
TITLES = dict(QUANTITY_TITLES, **DERIVATIVE_TITLES)
# The generated function each benchmark quantity runs, for its FLOP count (scene: full or derivatives).
FLOP_FUNCTIONS = {"gravity_terms": "gravity_terms", "bias": "inverse_dynamics",
                  "inverse_dynamics": "inverse_dynamics", "mass_matrix": "mass_matrix",
                  "forward_dynamics": "forward_dynamics", "quadratic_velocity_terms": "quadratic_velocity_terms",
                  "inverse_dynamics_derivatives": "inverse_dynamics_derivatives",
                  "forward_dynamics_derivatives": "forward_dynamics_derivatives"}


def loader_args(robot):
    """The rbdc options that load `robot` as bench/big_robots.json says (its mimic joints)."""
    entry = next(r for r in json.loads((ROOT / "bench" / "big_robots.json").read_text())["robots"] if r["name"] == robot)
    return ["--independent-mimic"] if entry.get("mimic") == "independent" else []


def configured_robots(build_dir):
    """{name: (URDF path, base)} of the big robots the configure step took (cmake/RbdcBigRobots.cmake
    says each on a status line; a corpus robot without its URDF is not there)."""
    base = {r["name"]: r["base"] for r in json.loads((ROOT / "bench" / "big_robots.json").read_text())["robots"]}
    log = (build_dir / "report-configure.log").read_text()
    return {name: (pathlib.Path(urdf), base[name])
            for name, urdf in re.findall(r"rbdc: big robot (\S+) \((\S+)\): scenes", log)}


def timings(build_dir, robots, args):
    """{case: {"ns": median, "min_ns": min}} of both programs, repetitions interleaved."""
    pattern = "^(" + "|".join(robots) + ")/"
    cases = {}
    for program in PROGRAMS:
        say(f"running {program} on {', '.join(robots)}")
        median = run_bench(build_dir, args.repetitions, args.min_time, pattern, program, interleave=True)
        minimum = bench_statistics(json.loads((build_dir / f"{program}.json").read_text()), "min")
        for name, ns in median.items():
            cases[name] = {"ns": round(ns, 2), "min_ns": round(minimum[name], 2)}
    return cases


def generated_headers(build_dir, robot):
    """The robot's implementation headers (<robot>/common/<function>_<hash>.hpp) over its scenes, once
    each, with the include root that holds them."""
    headers = {}
    for root in sorted((build_dir / "rbdc").glob(f"rbdc_gen_{robot}_*")):
        for header in sorted((root / robot / "common").glob("*.hpp")):
            headers.setdefault(header.name, (root, header))
    return list(headers.values())


def robot_table(robot, cases, counts):
    """{quantity: {implementation: {"ns", "min_ns", "flops"}}} of one robot."""
    table = {}
    for name, entry in cases.items():
        case_robot, quantity, implementation = name.split("/")
        if case_robot != robot:
            continue
        function = FLOP_FUNCTIONS.get(quantity)
        kind = "generic" if implementation == "runtime" else "generated"
        flops = counts.get(function, {}).get(kind) if function and implementation in (
            "generated_double", "runtime") else None
        table.setdefault(quantity, {})[implementation] = dict(entry, flops=flops)
    return table


def markdown(details):
    machine = details["machine"]
    lines = ["# rbdc on big robots (bench/report --big-robots)", "",
             f"Written by `bench/report --big-robots` on {details['date']}: the robots of "
             "bench/big_robots.json, generated at build time (nothing committed). Times: Google Benchmark "
             f"CPU time per call, {details['repetitions']} repetitions interleaved across cases, states "
             "cycled; median (min). How to read: [docs/benchmarks.md](../../docs/benchmarks.md), \"Big robots\".",
             "", f"- CPU: {machine['cpu']} ({machine['cores']} cores, kernel {machine['kernel']})",
             f"- compiler: {details['compiler']}; flags: {machine['flags']}",
             "- load average at the end: " + ", ".join(f"{x:.1f}" for x in machine["load_average"]), ""]
    for robot, data in details["robots"].items():
        lines += [f"## {robot} ({data['base']} base, `{data['urdf']}`)", "",
                  "| quantity | generated double | runtime | MuJoCo | runtime / generated | FLOPs (generated) "
                  "| ns / FLOP |", "|---|---|---|---|---|---|---|"]
        order = list(TITLES)  # the bundled robots' table order, the derivatives last
        for quantity, entries in sorted(data["times"].items(),
                                        key=lambda item: order.index(item[0]) if item[0] in order else len(order)):
            def cell(implementation):
                entry = entries.get(implementation)
                return f"{format_ns(entry['ns'])} ({format_ns(entry['min_ns'])})" if entry else "–"
            generated = entries.get("generated_double", {})
            flops = generated.get("flops")
            per_flop = f"{generated['ns'] / flops:.3f}" if flops else "–"
            lines.append(f"| {TITLES.get(quantity, quantity)} | {cell('generated_double')} | {cell('runtime')} | "
                         f"{cell('mujoco')} | {ratio(entries.get('runtime', {}).get('ns'), generated.get('ns'))} | "
                         f"{flops or '–'} | {per_flop} |")
        lines += [""] + cost_table(robot, data["compile"]) + [""]
    return "\n".join(lines) + "\n"


def report(build_root, compiler, args):
    build_dir = build_root / "build-report-big"
    build(build_dir, compiler, "native", PROGRAMS + ["rbdc-model"], args.jobs,
          options=["-DRBDC_BENCH_BIG_ROBOTS=ON", "-DRBDC_BENCH_DERIVATIVES=ON"])
    robots = configured_robots(build_dir)
    if not robots:
        say("no big robot configured (the corpus lacks them?): nothing to report")
        return
    cases = timings(build_dir, robots, args)
    details = {"date": datetime.date.today().isoformat(), "repetitions": args.repetitions,
               "compiler": compiler_version(compiler), "robots": {}}
    for robot, (urdf, base) in robots.items():
        counts = {}
        for scene in ("full", "derivatives"):
            for function, kinds in flop_counts(build_dir, scene, {robot: (urdf, base)},
                                               loader_args(robot)).get(robot, {}).items():
                counts.setdefault(function, kinds)
        details["robots"][robot] = {"urdf": os.path.relpath(urdf, ROOT), "base": base,
                                    "times": robot_table(robot, cases, counts),
                                    "compile": compile_costs(generated_headers(build_dir, robot), robot)}
    details["machine"] = machine_description({compiler: details["compiler"]}, "-O3 -march=native")
    write_result(RESULTS / "big_robots.json", json.dumps(details, indent=1, sort_keys=True) + "\n")
    write_result(RESULTS / "big_robots.md", markdown(details))
    say(f"wrote {RESULTS / 'big_robots.md'} and big_robots.json")
