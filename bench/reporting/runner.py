"""Building and running the benchmark programs for bench/report: configure and build a build
directory, run a Google Benchmark program, count FLOPs (`rbdc flops`) and instructions (callgrind), and
describe the machine."""
import atexit
import glob
import json
import os
import pathlib
import platform
import re
import shutil
import subprocess
import sys

from .common import ROBOTS, ROOT, say

COMPILERS = {"gcc": ("gcc", "g++"), "clang": ("clang", "clang++")}


def run(command, log=None, env=None, cwd=ROOT):
    """Runs a command; on failure prints its log and stops the report."""
    say("$ " + " ".join(str(c) for c in command))
    if log is None:
        result = subprocess.run(command, cwd=cwd, env=env)
    else:
        with open(log, "w") as out:
            result = subprocess.run(command, cwd=cwd, env=env, stdout=out, stderr=subprocess.STDOUT)
    if result.returncode != 0:
        if log is not None:
            sys.stdout.write(pathlib.Path(log).read_text()[-6000:])
        sys.exit(f"bench/report: failed ({result.returncode}): {' '.join(str(c) for c in command)}")


def build(build_dir, compiler, march, targets, jobs, options=()):
    """Configures a Release build (tests off, and the extra CMake `options`) and builds the targets."""
    c_compiler, cxx_compiler = COMPILERS[compiler]
    build_dir.mkdir(parents=True, exist_ok=True)
    options = [f"-DCMAKE_C_COMPILER={c_compiler}", f"-DCMAKE_CXX_COMPILER={cxx_compiler}",
               "-DCMAKE_BUILD_TYPE=Release", "-DRBDC_BUILD_TESTS=OFF"] + list(options)
    options += ["-DRBDC_NATIVE=ON"] if march == "native" else \
        ["-DRBDC_NATIVE=OFF", f"-DCMAKE_CXX_FLAGS=-march={march}"]
    run(["cmake", "-S", ROOT, "-B", build_dir] + options, log=build_dir / "report-configure.log")
    say(f"building {', '.join(targets)} with {cxx_compiler} (-j{jobs}; generated code takes minutes)")
    run(["cmake", "--build", build_dir, "-j", str(jobs), "--target"] + targets,
        log=build_dir / "report-build.log")


def run_bench(build_dir, repetitions, min_time, filter_, program="rbdc-bench", interleave=False,
              statistic="median"):
    """Runs a bench program (its console output is the progress) and returns {name: cpu ns}, the
    median (or min) over repetitions; with `interleave` the repetitions of all cases are randomly
    interleaved instead of run back to back. Each call runs a fresh copy of the program: its code in
    other physical pages than the last run's, which moves the long generated functions by up to 170 %
    (docs/benchmarks.md, "Long straight-line functions and the binary's pages"), so that several
    runs sample several placements."""
    out = build_dir / f"{program}.json"
    command = [fresh_copy(build_dir / "bin" / program), f"--benchmark_repetitions={repetitions}",
               f"--benchmark_min_time={min_time}", f"--benchmark_filter={filter_}",
               f"--benchmark_out={out}", "--benchmark_out_format=json"]
    command += ["--benchmark_enable_random_interleaving=true"] if interleave else \
        ["--benchmark_report_aggregates_only=true"]
    run(command)
    return bench_statistics(json.loads(out.read_text()), statistic)


_copies = []


def fresh_copy(program):
    """A new copy of `program` beside it, removed when the report exits. The copies stay until then,
    so that no copy's pages are the ones an earlier copy just gave back."""
    if not _copies:
        atexit.register(lambda: [copy.unlink(missing_ok=True) for copy in _copies])
    copy = program.with_name(f".{program.name}.run{len(_copies)}.{os.getpid()}")
    shutil.copy2(program, copy)
    _copies.append(copy)
    return copy


def bench_statistics(results, statistic):
    """{case: cpu ns} from Google Benchmark JSON: the median aggregate, or the min over iterations."""
    values = {}
    for row in results["benchmarks"]:
        if statistic == "median" and row.get("aggregate_name") == "median":
            values[row["run_name"]] = row["cpu_time"]  # time_unit ns (the default)
        elif statistic == "min" and row.get("run_type") == "iteration":
            name = row["run_name"]
            values[name] = min(values.get(name, float("inf")), row["cpu_time"])
    return values


def flop_counts(build_dir, scene=None, robots=None, loader_args=()):
    """{robot: {function: {"generated": total, "generic": total}}} from `rbdc flops --json`, for
    `robots` ({name: (URDF path, base)}; default: the bundled robots), loaded with `loader_args`
    (`--independent-mimic`: as the benchmarks load them)."""
    counts = {}
    env = dict(os.environ, RBDC_BUILD_DIR=str(build_dir))
    if robots is None:
        robots = {robot: (ROOT / "robots" / f"{robot}.urdf", base) for robot, base in ROBOTS.items()}
    for robot, (urdf, base) in robots.items():
        if not urdf.exists():
            continue
        scene_args = ["--scene", ROOT / "scenes" / f"{scene}.yaml"] if scene else []
        result = subprocess.run([ROOT / "rbdc", "flops", urdf, f"--{base}-base", "--json", *loader_args] + scene_args,
                                cwd=ROOT, env=env, capture_output=True, text=True)
        if result.returncode != 0:
            say(f"rbdc flops failed for {robot}: {result.stderr.strip()[-400:]}")
            continue
        functions = json.loads(result.stdout)["functions"]
        counts[robot] = {name: {kind: data[kind]["total"] for kind in ("generated", "generic")}
                         for name, data in functions.items()}
    return counts



def count_instructions(build_dir, calls):
    """Instructions per call for every case, from one callgrind run with a dump per case."""
    out_dir = build_dir / "callgrind"
    out_dir.mkdir(exist_ok=True)
    for old in out_dir.glob("callgrind.out*"):
        old.unlink()
    say(f"valgrind --tool=callgrind: {calls} calls per case (slow: a few minutes)")
    run(["valgrind", "--tool=callgrind", "--collect-atstart=no",
         f"--callgrind-out-file={out_dir}/callgrind.out.%p", build_dir / "bin" / "rbdc-bench",
         f"--count-instructions={calls}"], log=out_dir / "valgrind.log")
    counts = {}
    for dump in glob.glob(str(out_dir / "callgrind.out.*")):
        text = pathlib.Path(dump).read_text(errors="replace")
        trigger = re.search(r"^desc: Trigger: Client Request: (\S+)", text, re.M)
        total = re.search(r"^(?:summary|totals): (\d+)", text, re.M)
        if trigger and total:
            counts[trigger.group(1)] = int(total.group(1)) / calls
    return counts


def machine_description(compiler_versions, flags):
    # The model name alone ("AMD EPYC") does not tell Zen 3 from Zen 5: the family and model do.
    fields = {}
    for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
        key, _, value = line.partition(":")
        fields.setdefault(key.strip(), value.strip())
    cpu = fields.get("model name", "unknown")
    if "cpu family" in fields:
        cpu += f" (family {fields['cpu family']}, model {fields.get('model', '?')})"
    cores = os.cpu_count()
    return {"cpu": cpu, "cores": cores, "kernel": platform.release(),
            "compilers": compiler_versions, "flags": flags,
            "load_average": os.getloadavg()}


def compiler_version(compiler):
    result = subprocess.run([COMPILERS[compiler][1], "--version"], capture_output=True, text=True)
    return result.stdout.splitlines()[0] if result.returncode == 0 else compiler
