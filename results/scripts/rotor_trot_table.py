#!/usr/bin/env python3
"""The 10 s PD trot with and without the drive train (rbdc-sim --rotors): one markdown table of the
trunk's velocity and attitude and the feet's forces, each run against the first (the reference).
Usage: rotor_trot_table.py LABEL=RUN.csv ... (rbdc-sim --out files; angles in rad, forces in N)."""
import csv
import math
import sys

STEADY = 5.0  # s: the stride has reached full size (ramp) and the trot is periodic


def read(path):
    with open(path, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def summary(run):
    t = run["t"]
    steady = [k for k, time in enumerate(t) if time >= STEADY]
    first, last = steady[0], steady[-1]
    deg = 180 / math.pi
    stance = [run["LF_foot_fz"][k] for k in steady if run["LF_foot_contact"][k] > 0]
    return {
        "forward velocity, m/s (5-10 s)": (run["x"][last] - run["x"][first]) / (t[last] - t[first]),
        "x at 10 s, mm": 1e3 * run["x"][-1],
        "y at 10 s, mm": 1e3 * run["y"][-1],
        "mean z, mm (5-10 s)": 1e3 * sum(run["z"][k] for k in steady) / len(steady),
        "roll RMS, deg (5-10 s)": deg * rms([run["roll"][k] for k in steady]),
        "pitch RMS, deg (5-10 s)": deg * rms([run["pitch"][k] for k in steady]),
        "yaw at 10 s, deg": deg * run["yaw"][-1],
        "LF f_z mean in stance, N": sum(stance) / len(stance),
        "LF f_z peak, N": max(run["LF_foot_fz"][k] for k in steady),
        "LF stance fraction": len(stance) / len(steady),
    }


def gaps(run, reference):
    """Largest differences over the whole run (the runs share the time samples)."""
    n = min(len(run["t"]), len(reference["t"]))
    deg = 180 / math.pi
    return {
        "max Δ position, mm": 1e3 * max(math.dist((run["x"][k], run["y"][k], run["z"][k]),
                                                     (reference["x"][k], reference["y"][k], reference["z"][k]))
                                           for k in range(n)),
        "max Δ roll, Δ pitch, deg": "%.3f, %.3f" % tuple(
            deg * max(abs(run[a][k] - reference[a][k]) for k in range(n)) for a in ("roll", "pitch")),
        "RMS Δ LF f_z, N": rms([run["LF_foot_fz"][k] - reference["LF_foot_fz"][k] for k in range(n)]),
    }


def main(argv):
    runs = [(arg.split("=", 1)[0], read(arg.split("=", 1)[1])) for arg in argv]
    labels = [label for label, _ in runs]
    rows = {}
    for label, run in runs:
        for key, value in {**summary(run), **gaps(run, runs[0][1])}.items():
            rows.setdefault(key, []).append(value)
    print("| quantity | " + " | ".join(labels) + " |")
    print("|---|" + "---|" * len(labels))
    for key, values in rows.items():
        cells = [v if isinstance(v, str) else "%.4g" % v for v in values]
        print("| %s | %s |" % (key, " | ".join(cells)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
