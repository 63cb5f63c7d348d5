#!/bin/sh
# Regenerates results/osc/: the 10 s Mini Cheetah trot under the three controllers (trot_summary.md),
# its figures (trot_attitude.png, trot_grf.png) and the scaling study (scaling.md, scaling.json,
# scaling_*.png). Usage: results/scripts/osc.sh [BUILD_DIR]   (default: build; needs rbdc-osc-trot,
# rbdc-model and rbdc-osc-scaling-timer)
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/osc"
mkdir -p "$out"

# The per-millisecond traces stay out of git (MBs); the table and figures are committed.
"$build/bin/rbdc-osc-trot" --duration 10 --out "$scratch"
cp "$scratch/summary.md" "$out/trot_summary.md"
/usr/bin/python3 "$root/results/scripts/plot_osc_trot.py" "$scratch" "$out"
/usr/bin/python3 "$root/tools/scaling_study.py" --build-dir "$build" --out "$out"
echo "results written to $out"
