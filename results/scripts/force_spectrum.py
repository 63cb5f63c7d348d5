#!/usr/bin/python3
"""Chatter measure for a foot-force trace: the share of the force signal's energy above a cut-off
frequency (default 500 Hz) and its RMS in newtons, per foot and axis, from an rbdc-sim CSV sampled
at 1e-4 s (--sample-interval 1e-4; Nyquist 5 kHz).

Usage: force_spectrum.py TROT.csv [--cutoff HZ] [--from S]   (prints a Markdown table)
"""
import argparse
import csv

import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("--cutoff", type=float, default=500.0, help="Hz")
    parser.add_argument("--from", dest="start", type=float, default=1.0,
                        help="skip the start-up (s)")
    parser.add_argument("--label", default="", help="first column of the table")
    args = parser.parse_args()
    with open(args.csv) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["t"]) for r in rows])
    keep = t >= args.start
    dt = float(np.median(np.diff(t)))
    print(f"| {args.label or args.csv} | sample {dt:.0e} s, cut-off {args.cutoff:g} Hz | "
          "energy share above | RMS above (N) |")
    print("|---|---|---|---|")
    for foot in ("LF_foot", "RF_foot", "LH_foot", "RH_foot"):
        for axis in ("fx", "fy", "fz"):
            x = np.array([float(r[f"{foot}_{axis}"]) for r in rows])[keep]
            x = x - x.mean()
            spectrum = np.abs(np.fft.rfft(x)) ** 2
            freq = np.fft.rfftfreq(len(x), dt)
            total = spectrum.sum()
            high = spectrum[freq > args.cutoff].sum()
            # Parseval: the RMS of the high-passed signal.
            rms = np.sqrt(2 * high / len(x) ** 2)
            share = high / total if total > 0 else 0.0
            print(f"| {foot} {axis} | | {100 * share:.3f} % | {rms:.3f} |")


if __name__ == "__main__":
    main()
