#!/usr/bin/python3
"""Figures of the rbdc-osc-trot traces (paper 001 Figs. 9, 11 and 12 for the Mini Cheetah).

Usage: results/scripts/plot_osc_trot.py TRACE_DIR OUT_DIR [--step-start S]   (results/scripts/osc.sh runs it)
TRACE_DIR holds osc.csv, osc-open.csv and raibert.csv written by `rbdc-osc-trot --out TRACE_DIR`.
Writes OUT_DIR/trot_attitude.png (roll and pitch with their set-points over 0.6 s) and
OUT_DIR/trot_grf.png (ground reaction forces of one stance foot over one step, closed chain vs
open chain with measured forces, as Fig. 11).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from result_files import save_figure  # noqa: E402

CONTROLLERS = [("osc", "OSC, closed chain (no force sensing)", "C0"),
               ("osc-open", "OSC, open chain + measured forces (Eq. 50)", "C1"),
               ("raibert", "hip-torque PD (Eqs. 56-57)", "C2")]


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def window(trace, start, end):
    keep = [i for i, t in enumerate(trace["t"]) if start <= t < end]
    return {key: [values[i] for i in keep] for key, values in trace.items()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("traces")
    parser.add_argument("out")
    parser.add_argument("--step-start", type=float, default=6.0,
                        help="start of the LF+RH stance step shown in the GRF figure (s)")
    parser.add_argument("--step", type=float, default=0.15, help="step duration (s)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    traces = {name: load(os.path.join(args.traces, name + ".csv")) for name, _, _ in CONTROLLERS
              if os.path.exists(os.path.join(args.traces, name + ".csv"))}

    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    start, end = args.step_start, args.step_start + 4 * args.step
    for name, label, color in CONTROLLERS:
        if name not in traces:
            continue
        w = window(traces[name], start, end)
        axes[0].plot(w["t"], w["vx"], color=color, label=label)
        axes[1].plot(w["t"], w["roll"], color=color, label=label)
        axes[1].plot(w["t"], w["roll_desired"], color=color, linestyle=":")
        axes[2].plot(w["t"], w["pitch"], color=color)
        axes[2].plot(w["t"], w["pitch_desired"], color=color, linestyle=":")
    axes[0].set_ylabel("forward speed (m/s)")
    axes[1].set_ylabel("roll (deg)")
    axes[2].set_ylabel("pitch (deg)")
    axes[2].set_xlabel("t (s); dotted: cubic set-points (Eqs. 51-52)")
    axes[0].legend(fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle("Mini Cheetah trot, 4 steps (cf. paper 001 Figs. 9 and 12)")
    fig.tight_layout()
    save_figure(fig, os.path.join(args.out, "trot_attitude.png"), dpi=110)

    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    for name, label, color in CONTROLLERS[:2]:
        if name not in traces:
            continue
        w = window(traces[name], args.step_start, args.step_start + args.step)
        t = [x - args.step_start for x in w["t"]]
        for ax, axis in zip(axes, "xyz"):
            ax.plot(t, w["LF_f" + axis], color=color, label=label)
    for ax, axis in zip(axes, "xyz"):
        ax.set_ylabel(f"LF GRF {axis} (N)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[2].set_xlabel("time in stance (s)")
    fig.suptitle("Ground reaction force of the LF foot over one stance (cf. paper 001 Fig. 11)")
    fig.tight_layout()
    save_figure(fig, os.path.join(args.out, "trot_grf.png"), dpi=110)


if __name__ == "__main__":
    main()
