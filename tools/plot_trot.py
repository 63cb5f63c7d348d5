#!/usr/bin/python3
"""A picture of one rbdc-sim run: trunk height and forward position, roll and pitch, and the feet's
normal forces against time, from the CSV that `rbdc-sim --out` writes.

Usage: tools/plot_trot.py TRAJECTORY.csv OUT.png
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from result_files import save_figure  # noqa: E402


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    with open(argv[1]) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{argv[1]}: no samples")
    column = {key: [float(r[key]) for r in rows] for key in rows[0]}
    t = column["t"]
    feet = [key[:-len("_fz")] for key in column if key.endswith("_fz")]

    fig, (pos, att, force) = plt.subplots(3, 1, sharex=True, figsize=(8, 8))
    pos.plot(t, column["x"], label="x (forward)")
    pos.plot(t, column["z"], label="z (height)")
    pos.set_ylabel("trunk position [m]")
    pos.legend(loc="upper left")
    att.plot(t, [math.degrees(a) for a in column["roll"]], label="roll")
    att.plot(t, [math.degrees(a) for a in column["pitch"]], label="pitch")
    att.set_ylabel("attitude [deg]")
    att.legend(loc="upper left")
    for foot in feet:
        force.plot(t, column[foot + "_fz"], label=foot, linewidth=0.8)
    force.set_ylabel("normal force [N]")
    force.set_xlabel("time [s]")
    force.legend(loc="upper right", ncol=len(feet))
    fig.suptitle("rbdc-sim: PD trot on the generated Mini Cheetah dynamics")
    fig.tight_layout()
    save_figure(fig, argv[2], dpi=110)
    print(f"plot_trot: wrote {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
