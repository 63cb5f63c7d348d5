#!/bin/sh
# Regenerates results/sim/rotors.md: the 10 s PD trot of rbdc-sim without the drive train (paper
# 000's model), with MIT's rotors reduced to armature, and with the rotors as bodies (--rotors,
# docs/simulator.md), all on the runtime dynamics, plus the generated dynamics without rotors as a
# check that both implementations give the same run. Usage: results/scripts/sim_rotors.sh [BUILD_DIR]
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/sim/rotors.md"
duration="${DURATION:-10}"
for rotors in none armature full; do
  "$build/bin/rbdc-sim" --quiet --duration "$duration" --dynamics runtime --rotors "$rotors" \
    --out "$scratch/$rotors.csv" > "$scratch/$rotors.txt"
done
"$build/bin/rbdc-sim" --quiet --duration "$duration" --out "$scratch/generated.csv" > "$scratch/generated.txt"
{
  echo "# The trot with the drive train ($duration s, dt 1e-4 s, PD trot of paper 000)"
  echo
  echo "rbdc-sim --dynamics runtime --rotors none | armature | full (robots/mini_cheetah_rotors.topology.yaml:"
  echo "twelve rotors, 0.66 kg, reflected inertia 0.0023 kg m² at abad and hip, 0.0055 kg m² at the knee);"
  echo "the last column is the generated dynamics without rotors. The controller is the same in every run"
  echo "(its gains and trajectories do not know the rotors). Written by results/scripts/sim_rotors.sh."
  echo
  python3 "$root/results/scripts/rotor_trot_table.py" "none (paper 000)=$scratch/none.csv" \
    "armature=$scratch/armature.csv" "full rotors=$scratch/full.csv" "none, generated=$scratch/generated.csv"
  echo
  echo "Wall time per run (this machine, shared):"
  for run in none armature full generated; do
    echo "- $run: $(grep '^simulated' "$scratch/$run.txt")"
  done
} > "$out"
