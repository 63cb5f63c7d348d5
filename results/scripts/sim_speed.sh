#!/bin/sh
# Writes results/sim/speed.txt: rbdc-sim's speed on 10 s of trot (Heun, dt 1e-4 s, generated
# dynamics) in a portable and, when given, a native (-DRBDC_NATIVE=ON) build: wall time of 3 runs
# interleaved across the builds (min and median), the per-phase profile (--profile), MuJoCo timed in
# the same rbdc-mujoco-compare run, and the instruction count of 1.5 s under callgrind (portable
# build only: valgrind cannot run -march=native code here).
# Usage: results/scripts/sim_speed.sh [PORTABLE_BUILD_DIR] [NATIVE_BUILD_DIR]   (default: build)
set -eu
. "$(dirname "$0")/common.sh"
native=${2:-}
builds="$build${native:+ $native}"
out="$root/results/sim/speed.txt"

label() {  # how a build directory is named in the output
  if [ "$1" = "$build" ]; then echo "portable ($(basename "$1"))"; else echo "native ($(basename "$1"))"; fi
}
wall() {  # seconds of one 10 s run
  "$1/bin/rbdc-sim" --quiet | sed -n 's/^simulated .* in \([0-9.]*\) s wall.*/\1/p'
}
min_median() {  # of the numbers on stdin
  sort -g | awk '{ v[NR] = $1 } END { printf "min %.3f s, median %.3f s", v[1], v[int((NR + 1) / 2)] }'
}

{
  echo "== rbdc-sim, 10 s trot, Heun, dt 1e-4 s, generated dynamics ($(date -u +%F), load average $(cut -d' ' -f1-3 /proc/loadavg))"
  for run in 1 2 3; do
    for b in $builds; do echo "$b $(wall "$b")"; done
  done > "$scratch/walls"
  for b in $builds; do
    echo "$(label "$b"): 3 interleaved runs, $(awk -v b="$b" '$1 == b { print $2 }' "$scratch/walls" | min_median)"
  done
  for b in $builds; do
    echo "== $(label "$b"): per-phase profile (timer overhead included)"
    "$b/bin/rbdc-sim" --quiet --profile
    echo "== $(label "$b"): rbdc-mujoco-compare, 10 s, wall times of the same run"
    "$b/bin/rbdc-mujoco-compare" --quiet --no-plots --out "$scratch/compare" 2> /dev/null | grep 'wall time\|speed-up'
  done
  echo "== $(label "$build"): the same with the force at the sphere centre and explicit friction"
  "$build/bin/rbdc-sim" --quiet --profile --contact-point off --friction isotropic --friction-update explicit
  echo "== $(label "$build"): the same on the runtime (reference) dynamics"
  "$build/bin/rbdc-sim" --quiet --dynamics runtime --profile
  if command -v valgrind > /dev/null; then
    echo "== $(label "$build"): callgrind, rbdc-sim --duration 1.5 --quiet"
    valgrind --tool=callgrind --callgrind-out-file="$scratch/callgrind.out" "$build/bin/rbdc-sim" --duration 1.5 --quiet \
      2>&1 | sed -n 's/.*Collected : \([0-9]*\)/instructions: \1/p'
  fi
} > "$(partial "$out")"
commit "$out"
echo "written $out"
