#!/bin/sh
# Regenerates results/osc/: the 10 s Mini Cheetah trot under the three controllers (trot_summary.md),
# its figures (trot_attitude.png, trot_grf.png), the scaling study (scaling.md, scaling.json,
# scaling_*.png) and Fig. 7 (ground_mass.png, ground_mass.md). Usage: results/scripts/osc.sh
# [BUILD_DIR]   (default: build; needs rbdc-osc-trot, rbdc-model, rbdc-osc-scaling-timer and
# rbdc-osc-ground-mass)
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/osc"
mkdir -p "$out"

# The per-millisecond traces stay out of git (MBs); the table and figures are committed.
"$build/bin/rbdc-osc-trot" --duration 10 --out "$scratch"
publish "$scratch/summary.md" "$out/trot_summary.md"
/usr/bin/python3 "$root/results/scripts/plot_osc_trot.py" "$scratch" "$out"
/usr/bin/python3 "$root/tools/scaling_study.py" --build-dir "$build" --out "$out"
"$root/results/scripts/osc_ground_mass.sh" "$build"
echo "results written to $out"
