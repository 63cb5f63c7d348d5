#!/usr/bin/env python3
"""The figures of docs/python.md: rbdc.compile of the Mini Cheetah `full` scene (first compile into
a fresh cache, then a cache hit in a new process), the single-call overhead of the Python module
over the same C++ function, 10^6-state batches against a C++ loop over the same generated code
(cxx_baseline.cpp, same flags), 1 against 2 threads (interleaved pairs: the median and range of
the pairs' ratios), and rbdc.dask on a LocalCluster with 1 and 2
worker processes (10^7 states, per-chunk checksums identical to a single-process run).
Usage: /usr/bin/python3 bench/python/measure.py [--states 1000000] [--dask-states 10000000] [--no-dask]
                                              [--quiet-load 0.6 [--quiet-wait 1800]]
Prints JSON with the 1-minute load average before each stage (with --quiet-load, each stage first
waits until it is below that). Single-thread figures are CPU time (they hold on a shared machine);
the thread and Dask scaling are wall time and need an otherwise idle machine. The first compile runs
with CCACHE_DISABLE=1 (rbdc.compile calls the compiler directly; this keeps a ccache wrapper given
as RBDC_CXX out of the figure)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))
CHEETAH = ROOT / "robots" / "mini_cheetah.urdf"


def best(function, number, repeat=7, timer=time.process_time, names=None):
    """Seconds per call: the best of `repeat` runs, in CPU time of this process by default (the
    figures then hold on a shared machine); the thread scaling needs wall time (time.perf_counter).
    `function` is a callable, or a statement run with `names` as its globals (no lambda around it)."""
    return min(timeit.repeat(function, number=number, repeat=repeat, timer=timer, globals=names)) / number


QUIET_WAIT_S = 1800  # --quiet-wait


def quiet(results, stage, threshold):
    """Waits (up to QUIET_WAIT_S) until the 1-minute load is below `threshold` (0: no wait); records the load."""
    deadline = time.monotonic() + QUIET_WAIT_S
    while threshold and os.getloadavg()[0] >= threshold and time.monotonic() < deadline:
        time.sleep(15)
    results.setdefault("load_1min_before", {})[stage] = round(os.getloadavg()[0], 2)


def compile_times(results, threshold):
    import rbdc
    quiet(results, "compile", threshold)
    start = time.perf_counter()
    module = rbdc.compile(CHEETAH)
    results["compile_s (first compile, or a hit with --keep-cache)"] = round(time.perf_counter() - start, 2)
    code = (f"import sys, time; t = time.perf_counter(); sys.path.insert(0, {str(ROOT / 'python')!r}); import rbdc; "
            f"rbdc.compile({str(CHEETAH)!r}); print(time.perf_counter() - t)")
    hits = [float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout)
            for _ in range(3)]
    results["compile_ccache"] = "off (CCACHE_DISABLE=1), compiler " + " ".join(rbdc.compiled._compiler())
    results["cache_hit_new_process_s (import rbdc + compile)"] = round(min(hits), 3)
    start = time.perf_counter()
    rbdc.compiled.cache_key(module.target)
    results["cache_key_s"] = round(time.perf_counter() - start, 4)
    return module


def states(n, seed=1):
    rng = np.random.default_rng(seed)
    return unit_quaternions(rng.uniform(-1, 1, (n, 19))), rng.uniform(-1, 1, (n, 18)), rng.uniform(-1, 1, (n, 18))


def unit_quaternions(q):
    q = q.copy()
    q[:, 3:7] /= np.linalg.norm(q[:, 3:7], axis=1, keepdims=True)
    return q


def cxx_baseline(module, n):
    entry = module.cache_entry
    binary = entry.parent / f"cxx_baseline_{entry.name}"
    if not binary.exists():
        from rbdc.compiled import _compiler, _flags
        flags = [f for f in _flags() if f not in ("-fPIC", "-fvisibility=hidden")]
        subprocess.run([*_compiler(), *flags, f"-I{entry / 'src'}", "-I/usr/include/eigen3",
                        str(Path(__file__).with_name("cxx_baseline.cpp")), "-o", str(binary)], check=True)
    return json.loads(subprocess.run([str(binary), str(n)], capture_output=True, text=True, check=True).stdout)


def thread_scaling(run, pairs=7):
    """Wall time of run(1) against run(2) in `pairs` interleaved pairs (a neighbour's burst on a
    shared machine then hits both sides alike): each pair's ratio, and the best time of each side."""
    ratios, ones, twos = [], [], []
    for _ in range(pairs):
        for threads, times in ((1, ones), (2, twos)):
            start = time.perf_counter()
            run(threads)
            times.append(time.perf_counter() - start)
        ratios.append(ones[-1] / twos[-1])
    return ratios, min(ones), min(twos)


def python_figures(module, n, results, threshold):
    q, v, a = states(n)
    quiet(results, "single_and_batch", threshold)
    cxx = cxx_baseline(module, n)
    for name, args, size in (("inverse_dynamics", (q, v, a), (n, 18)), ("mass_matrix", (q,), (n, 18, 18))):
        f = getattr(module, name)
        # One state as a user holds it (its own C-contiguous float64 arrays), the call as written.
        names = {"f": f, "out": np.empty(size[1:]), **{k: x[0].copy() for k, x in zip("qva", args)}}
        call = f"f({', '.join('qva'[:len(args)])}"
        single = best(call + ")", 20000, names=names)
        single_out = best(call + ", out=out)", 20000, names=names)
        out = np.empty(size)
        one = best(lambda: f(*args, out=out, threads=1), 1, 3) / n
        quiet(results, f"{name}_threads", threshold)
        ratios, one_wall, two_wall = thread_scaling(lambda threads: f(*args, out=out, threads=threads))
        one_wall, two_wall = one_wall / n, two_wall / n
        results[name] = {"python_single_ns": round(1e9 * single, 1), "cxx_single_ns": cxx[name]["single_ns"],
                         "overhead_ns": round(1e9 * single - cxx[name]["single_ns"], 1),
                         "python_single_out_ns": round(1e9 * single_out, 1),
                         "python_batch_1_thread_ns_per_state": round(1e9 * one, 1),
                         "cxx_batch_ns_per_state": cxx[name]["batch_ns_per_state"],
                         "batch_ratio_python_over_cxx": round(1e9 * one / cxx[name]["batch_ns_per_state"], 3),
                         "wall_1_thread_ns_per_state": round(1e9 * one_wall, 1),
                         "wall_2_threads_ns_per_state": round(1e9 * two_wall, 1),
                         "speedup_2_threads_wall_median": round(float(np.median(ratios)), 2),
                         "speedup_2_threads_wall_min_max": [round(min(ratios), 2), round(max(ratios), 2)]}


def dask_figures(module, n, results, threshold):
    import dask
    import dask.array as da
    from dask.distributed import Client, LocalCluster
    import rbdc.dask

    def checksums():
        random = da.random.RandomState(42)
        chunk = 250_000
        Q, V, A = (random.uniform(-1, 1, (n, size), chunks=(chunk, size)) for size in (19, 18, 18))
        Q = Q.map_blocks(unit_quaternions)  # the generated code refuses others
        tau = rbdc.dask.map(module, "inverse_dynamics", Q, V, A)
        return da.map_blocks(lambda b: b.sum(axis=0, keepdims=True), tau, chunks=((1,) * tau.numblocks[0], (18,)))

    figures = {}
    os.environ["PYTHONPATH"] = str(ROOT / "python")  # for the worker processes
    with dask.config.set(scheduler="synchronous"):
        start = time.perf_counter()
        reference = checksums().compute()
        figures["single_process_s"] = round(time.perf_counter() - start, 2)
    for workers in (1, 2):
        quiet(results, f"dask_{workers}_workers", threshold)
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            checksums().compute()  # every worker loads the module once
            start = time.perf_counter()
            sums = checksums().compute()
            figures[f"{workers}_workers_s"] = round(time.perf_counter() - start, 2)
            figures[f"{workers}_workers_identical"] = bool(np.array_equal(sums, reference))
    figures["speedup_2_workers"] = round(figures["1_workers_s"] / figures["2_workers_s"], 2)
    results[f"dask_{n}_states"] = figures


def machine():
    lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    model = next((line.split(":", 1)[1].strip() for line in lscpu.splitlines() if line.startswith("Model name")), "?")
    return f"{model}, {os.cpu_count()} cores"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--states", type=int, default=1_000_000)
    parser.add_argument("--dask-states", type=int, default=10_000_000)
    parser.add_argument("--no-dask", action="store_true")
    parser.add_argument("--keep-cache", action="store_true", help="use the user's cache (no first compile)")
    parser.add_argument("--quiet-load", type=float, default=0,
                        help="before each stage, wait (up to --quiet-wait s) until the 1-minute load is below this")
    parser.add_argument("--quiet-wait", type=float, default=1800)
    args = parser.parse_args()
    global QUIET_WAIT_S
    QUIET_WAIT_S = args.quiet_wait
    if not args.keep_cache:
        os.environ["RBDC_CACHE_DIR"] = tempfile.mkdtemp(prefix="rbdc-measure-")
    os.environ["CCACHE_DISABLE"] = "1"
    results = {"machine": machine()}
    module = compile_times(results, args.quiet_load)
    print(json.dumps(results, indent=1), flush=True)  # each stage as it ends: the whole run takes minutes
    python_figures(module, args.states, results, args.quiet_load)
    print(json.dumps(results, indent=1), flush=True)
    if not args.no_dask:
        dask_figures(module, args.dask_states, results, args.quiet_load)
    results["load_average_after"] = os.getloadavg()
    print(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
