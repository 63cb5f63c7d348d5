"""What each generated header costs the compiler (issue 20: ≤ 20 s and ≤ 2 GB per header, a humanoid's
`full` and `derivatives` scenes together ≤ 60 s): g++ -O3 -march=native on a translation unit that
instantiates the header's one function for double, one header at a time, with wall time and peak
memory by GNU time. `bench/report --compile-cost` measures the bundled robots' committed headers of
those two scenes, alone and all in one translation unit, into results/bench/compile_cost.md and .json;
`--big-robots` uses the per-header measurement for the robots it generates."""
import datetime
import json
import pathlib
import re
import subprocess
import tempfile

from result_files import write_result

from .common import RESULTS, ROBOTS, ROOT, say
from .runner import compiler_version, machine_description

COMPILE_FLAGS = ["-std=c++17", "-O3", "-march=native", "-DNDEBUG", "-I/usr/include/eigen3"]
SCENES = ("full", "derivatives")


def _function(header):
    """The function that a <function>_<hash>.hpp implementation header defines."""
    return re.sub(r"_[0-9a-f]{12}$", "", header.stem)


def _compile(root, robot, headers):
    """g++ on one translation unit that includes `headers` and takes the address of each one's function
    for double: (seconds, peak MB) by GNU time, or None (said) when it does not compile."""
    source = "".join(f'#include "{robot}/common/{h.name}"\n' for h in headers)
    source += "".join(f"void* rbdc_instantiated_{k} = reinterpret_cast<void*>("
                      f"&rbdc_gen::{robot}::common::{h.stem}::{_function(h)}<double>);\n"
                      for k, h in enumerate(headers))
    with tempfile.TemporaryDirectory() as scratch:
        tu = pathlib.Path(scratch) / "cost.cpp"
        tu.write_text(source)
        timing = pathlib.Path(scratch) / "time.txt"
        result = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", timing, "g++"] + COMPILE_FLAGS
                                + [f"-I{root}", "-c", tu, "-o", pathlib.Path(scratch) / "cost.o"],
                                capture_output=True, text=True)
        if result.returncode != 0:
            say(f"compile of {', '.join(h.name for h in headers)} failed: {result.stderr.strip()[-400:]}")
            return None
        seconds, kilobytes = timing.read_text().split()[-2:]
    return float(seconds), round(int(kilobytes) / 1024)


def compile_cost(root, header, robot):
    """_compile of the header alone, with the header's size: a row of the tables."""
    cost = _compile(root, robot, [header])
    if cost is None:
        return None
    text = header.read_text()
    return {"function": _function(header), "header": header.name, "bytes": len(text.encode()),
            "lines": text.count("\n"), "seconds": cost[0], "peak_mb": cost[1]}


def compile_costs(headers, robot):
    """compile_cost of each (include root, header), the ones that compiled."""
    rows = []
    for root, header in headers:
        say(f"compiling {robot}/common/{header.name} alone (g++ -O3)")
        row = compile_cost(root, header, robot)
        if row:
            rows.append(row)
    return rows


def cost_table(robot, costs):
    """Markdown lines: one row per header, slowest first, and the totals."""
    lines = [f"Each generated header of {robot} alone (g++ -O3 -march=native, its function instantiated "
             "for double):", "", "| function | header KB | lines | g++ s | peak MB |", "|---|---|---|---|---|"]
    for row in sorted(costs, key=lambda r: -r["seconds"]):
        lines.append(f"| {row['function']} | {row['bytes'] / 1024:.0f} | {row['lines']} | "
                     f"{row['seconds']:.1f} | {row['peak_mb']} |")
    if costs:
        lines += ["", f"All {len(costs)} headers: {sum(r['seconds'] for r in costs):.1f} s of g++, "
                  f"{sum(r['bytes'] for r in costs) / 2**20:.1f} MB of C++; the slowest "
                  f"{max(r['seconds'] for r in costs):.1f} s, the most memory "
                  f"{max(r['peak_mb'] for r in costs)} MB."]
    return lines


def scene_headers(robot):
    """The committed implementation headers (generated/<robot>/common/…) that the robot's `full` and
    `derivatives` scenes include, once each, with generated/ as their include root."""
    generated = ROOT / "generated"
    names = set()
    for scene in SCENES:
        for header in (generated / robot / scene).glob("*.hpp"):
            names.update(re.findall(rf'#include "{robot}/common/([^"]+\.hpp)"', header.read_text()))
    return [(generated, generated / robot / "common" / name) for name in sorted(names)]


def report():
    details = {"date": datetime.date.today().isoformat(), "scenes": list(SCENES), "robots": {}}
    for robot in ROBOTS:
        headers = scene_headers(robot)
        say(f"compiling {robot}'s {' and '.join(SCENES)} headers in one translation unit (g++ -O3)")
        together = _compile(ROOT / "generated", robot, [header for _, header in headers])
        details["robots"][robot] = {"headers": compile_costs(headers, robot), "one_unit": together}
    details["compiler"] = compiler_version("gcc")
    details["machine"] = machine_description({"gcc": details["compiler"]}, " ".join(COMPILE_FLAGS[1:3]))
    write_result(RESULTS / "compile_cost.json", json.dumps(details, indent=1, sort_keys=True) + "\n")
    write_result(RESULTS / "compile_cost.md", markdown(details))
    say(f"wrote {RESULTS / 'compile_cost.md'} and compile_cost.json")


def markdown(details):
    machine = details["machine"]
    lines = ["# What the bundled robots' generated headers cost the compiler (bench/report --compile-cost)", "",
             f"Written by `bench/report --compile-cost` on {details['date']}: every header of generated/ that "
             "the `full` and `derivatives` scenes include, each compiled alone, one at a time. The big robots "
             "(TALOS, a 100-link chain) are in big_robots.md, measured the same way.", "",
             f"- CPU: {machine['cpu']} ({machine['cores']} cores, kernel {machine['kernel']})",
             f"- compiler: {details['compiler']}", ""]
    for robot, costs in details["robots"].items():
        lines += [f"## {robot}", ""] + cost_table(robot, costs["headers"]) + [""]
        if costs["one_unit"]:
            seconds, megabytes = costs["one_unit"]
            lines += [f"Its {' and '.join(f'`{s}`' for s in details['scenes'])} headers in one translation unit, "
                      f"every function instantiated for double: **{seconds:.1f} s, {megabytes} MB**.", ""]
    return "\n".join(lines) + "\n"
