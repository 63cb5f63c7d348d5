#!/usr/bin/env bash
# Before/after against Pinocchio for one robot: alternates runs of two binaries built by
# generated_vs_pinocchio.sh (e.g. with RUNS=0 from two checkouts into two OUT directories), before
# first, each run from a fresh copy of its binary, and prints peer_ratios.py's table with the before
# column. Alternating matters: this machine class runs 20-40 % slower for minutes at a time, and a
# binary's speed can depend on the file it runs from (docs/performance.md, "what the timings move with").
# Usage: bench/peer/alternate_runs.sh BEFORE_OUT AFTER_OUT ROBOT URDF --floating-base|--fixed-base [--independent-mimic]
# Environment: RUNS (pairs of runs, default 3), TIME_CPU (default 1); JSON and console output go to
# AFTER_OUT/ROBOT/ab/{before,after}_K.{json,txt}.
set -euo pipefail
[ $# -ge 5 ] || { sed -n '2,10p' "$0" >&2; exit 2; }
before="$(realpath "$1")" after="$(realpath "$2")" robot="$3"
shift 3
dir="$after/$robot/ab"
mkdir -p "$dir"
rm -f "$dir"/*.json "$dir"/*.txt
for k in $(seq 1 "${RUNS:-3}"); do
  for side in before after; do
    out="$before"
    [ "$side" = after ] && out="$after"
    copy="$out/$robot/generated_vs_pinocchio.alternate"
    cp "$out/$robot/generated_vs_pinocchio" "$copy"
    echo "run $k, $side" >&2
    if ! nice -n 19 taskset -c "${TIME_CPU:-1}" "$copy" "$@" --benchmark_repetitions=7 \
        --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
        --benchmark_out="$dir/${side}_$k.json" --benchmark_out_format=json > "$dir/${side}_$k.txt" 2>&1; then
      cat "$dir/${side}_$k.txt" >&2
      exit 1
    fi
    rm "$copy"
  done
done
python3 "$(dirname "$0")/peer_ratios.py" "$dir"/after_*.json --before "$dir"/before_*.json
