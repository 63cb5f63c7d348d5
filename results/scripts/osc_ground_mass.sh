#!/bin/sh
# Regenerates results/osc/ground_mass.png and ground_mass.md: paper 001 Fig. 7 (closed-chain error
# against ground mass at one mid-stance configuration, trot pair LF + RH pinned) and the
# 500-configuration study beside it. Usage: results/scripts/osc_ground_mass.sh [BUILD_DIR]
# (default: build; needs rbdc-osc-ground-mass). Takes a few seconds.
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/osc"
mkdir -p "$out"
"$build/bin/rbdc-osc-ground-mass" --configurations 500 > "$scratch/ground_mass.json"
/usr/bin/python3 "$root/results/scripts/plot_osc_ground_mass.py" "$scratch/ground_mass.json" "$out"
echo "results written to $out/ground_mass.png and ground_mass.md"
