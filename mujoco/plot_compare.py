#!/usr/bin/python3
"""Draws paper 000's Figures 5 and 6 for one rbdc-mujoco-compare output directory.

Usage: plot_compare.py DIR   (reads DIR/ours.csv and DIR/mujoco.csv, writes DIR/trunk_pose.png and
DIR/lf_contact.png). Standard library + matplotlib only.
"""
import csv
import math
import os
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend choice)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from result_files import save_figure  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_compare.py: {path} has no data rows")
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def trunk_pose_figure(ours, mujoco, out):
    """Figure 5: trunk position (mm) and ZYX Euler angles (deg) of both simulators."""
    fig, axes = plt.subplots(2, 3, figsize=(12, 6), sharex=True)
    for col, key in enumerate(("x", "y", "z")):
        ax = axes[0][col]
        ax.plot(ours["t"], [1e3 * v for v in ours[key]], label="rbdc (ours)")
        ax.plot(mujoco["t"], [1e3 * v for v in mujoco[key]], "--", label="MuJoCo")
        ax.set_ylabel(f"{key} (mm)")
    for col, key in enumerate(("roll", "pitch", "yaw")):
        ax = axes[1][col]
        ax.plot(ours["t"], [math.degrees(v) for v in ours[key]], label="rbdc (ours)")
        ax.plot(mujoco["t"], [math.degrees(v) for v in mujoco[key]], "--", label="MuJoCo")
        ax.set_ylabel(f"{key} (deg)")
        ax.set_xlabel("t (s)")
    axes[0][0].legend()
    fig.suptitle("Trunk position and orientation (paper 000 Fig. 5)")
    fig.tight_layout()
    save_figure(fig, out, dpi=120)


def contact_figure(ours, mujoco, out, foot="LF_foot"):
    """Figure 6: left-foreleg contact activation and vertical contact force."""
    fig, axes = plt.subplots(2, 1, figsize=(12, 6), sharex=True)
    axes[0].step(ours["t"], ours[f"{foot}_contact"], where="post", label="rbdc (ours)")
    axes[0].step(mujoco["t"], [v + 0.02 for v in mujoco[f"{foot}_contact"]], "--", where="post",
                 label="MuJoCo (offset +0.02)")
    axes[0].set_ylabel("contact activation")
    axes[0].legend()
    axes[1].plot(ours["t"], ours[f"{foot}_fz"], label="rbdc (ours)")
    axes[1].plot(mujoco["t"], mujoco[f"{foot}_fz"], "--", label="MuJoCo")
    axes[1].set_ylabel("vertical force (N)")
    axes[1].set_xlabel("t (s)")
    fig.suptitle("Left foreleg contact (paper 000 Fig. 6)")
    fig.tight_layout()
    save_figure(fig, out, dpi=120)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    directory = Path(sys.argv[1])
    ours = read_columns(directory / "ours.csv")
    mujoco = read_columns(directory / "mujoco.csv")
    trunk_pose_figure(ours, mujoco, directory / "trunk_pose.png")
    contact_figure(ours, mujoco, directory / "lf_contact.png")


if __name__ == "__main__":
    main()
